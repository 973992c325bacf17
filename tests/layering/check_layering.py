#!/usr/bin/env python3
"""Checks that the source folders form a DAG in the documented order (docs/architecture.md, "Folder order").

A folder is the first two path components (renderer/scene, geometry/csg, tools/cli); its subfolders belong to it
(renderer/image/oiio is renderer/image). Every `#include "…"` of a project header in a source file is an edge from
the file's folder to the header's folder. The check fails on

  - an include that is not downward: each folder has a layer in LAYERS, and a folder may include folders of its own
    layer or lower ones, within its own group or a group it builds on (GROUP_BASES);
  - a folder cycle: folders of one layer may include each other, but never in a loop;
  - a folder that LAYERS does not place (a new folder is given its layer here and in docs/architecture.md).

Tests are left out: *_test.cpp files, *_test_support.* headers and tests/ stand above every folder (a scene-loader
test loads spheres, a CSG test builds boxes), so they may include any folder.

Usage: check_layering.py [SOURCE_DIR]   (default: the source tree this script is in). Exit 0 clean, 1 violations.
"""
import os
import re
import sys

# Low to high within each group. A folder may include folders of its own or a lower layer.
LAYERS = {
    "renderer": [
        ["renderer/math"],
        ["renderer/core"],
        ["renderer/embree", "renderer/colour", "renderer/sampling"],
        ["renderer/params", "renderer/bsdf"],
        ["renderer/plugin"],
        ["renderer/image", "renderer/cameras", "renderer/filters"],
        ["renderer/image_compare", "renderer/textures"],
        ["renderer/film", "renderer/lights", "renderer/materials"],
        ["renderer/scene"],
        ["renderer/render"],
        ["renderer/distributed"],
    ],
    "geometry": [
        ["geometry/polynomial", "geometry/curves", "geometry/field", "geometry/expression"],
        ["geometry/csg"],
        ["geometry/sphere", "geometry/box", "geometry/superquadric", "geometry/mesh", "geometry/plane", "geometry/disk",
         "geometry/rectangle", "geometry/cylinder", "geometry/cone", "geometry/torus"],
        ["geometry/implicit", "geometry/sweep", "geometry/isosurface"],
        ["geometry/polygonize", "geometry/abm_patch"],
    ],
    "integrators": [
        ["integrators/aov", "integrators/path", "integrators/preview"],
    ],
    "tools": [
        ["tools/cli"],
    ],
}
# The groups each group builds on: the renderer core names no plugin; geometry and integrators are plugins of the
# core and never name each other; tools use everything.
GROUP_BASES = {
    "renderer": [],
    "geometry": ["renderer"],
    "integrators": ["renderer"],
    "tools": ["renderer", "geometry", "integrators"],
}
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".inl")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def folder_of(path):
    parts = path.split("/")
    return "/".join(parts[:2]) if len(parts) > 2 else None


def is_test(path):
    name = os.path.basename(path)
    stem = name.rsplit(".", 1)[0]
    return path.startswith("tests/") or stem.endswith("_test") or stem.endswith("_test_support")


def layer_of(folder):
    group = folder.split("/")[0]
    for index, layer in enumerate(LAYERS.get(group, [])):
        if folder in layer:
            return group, index
    return group, None


def includes(root):
    """(file, line, including folder, included folder) for every project include between folders."""
    found = []
    for group in LAYERS:
        for directory, _, names in os.walk(os.path.join(root, group)):
            for name in sorted(names):
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root).replace(os.sep, "/")
                if is_test(path):
                    continue
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as source:
                    text = source.read()
                for match in INCLUDE.finditer(text):
                    target = match.group(1)
                    if target.split("/")[0] not in GROUP_BASES:  # a header beside the file, or a library's
                        target = os.path.normpath(os.path.join(os.path.dirname(path), target)).replace(os.sep, "/")
                        if not os.path.exists(os.path.join(root, target)):
                            continue
                    line = text.count("\n", 0, match.start()) + 1
                    found.append((path, line, folder_of(path), folder_of(target)))
    return found


def upward_includes(edges):
    problems = []
    for path, line, source, target in edges:
        if target is None or source == target:
            continue
        source_group, source_layer = layer_of(source)
        target_group, target_layer = layer_of(target)
        if source_layer is None or target_layer is None:
            continue  # reported as unplaced
        if target_group == source_group:
            if target_layer > source_layer:
                problems.append(f"{path}:{line}: upward include: {source} (layer {source_layer + 1} of {source_group}) "
                                f"includes {target} (layer {target_layer + 1})")
        elif target_group not in GROUP_BASES[source_group]:
            problems.append(f"{path}:{line}: upward include: {source_group}/ may not include {target_group}/ "
                            f"({source} includes {target})")
    return problems


def unplaced_folders(edges):
    folders = {folder for _, _, source, target in edges for folder in (source, target) if folder}
    return [f"folder {folder} has no layer: place it in LAYERS ({os.path.basename(__file__)}) and in "
            f"docs/architecture.md" for folder in sorted(folders) if layer_of(folder)[1] is None]


def folder_cycles(edges):
    """Strongly connected components of more than one folder (Tarjan), each with the includes that close it."""
    graph = {}
    example = {}
    for path, line, source, target in edges:
        if target is None or source == target:
            continue
        graph.setdefault(source, set()).add(target)
        graph.setdefault(target, set())
        example.setdefault((source, target), f"{path}:{line}")
    index, low, stack, on_stack, components = {}, {}, [], set(), []

    def connect(folder):  # recursion depth is bounded by the number of folders
        index[folder] = low[folder] = len(index)
        stack.append(folder)
        on_stack.add(folder)
        for target in sorted(graph[folder]):
            if target not in index:
                connect(target)
                low[folder] = min(low[folder], low[target])
            elif target in on_stack:
                low[folder] = min(low[folder], index[target])
        if low[folder] == index[folder]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == folder:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for folder in sorted(graph):
        if folder not in index:
            connect(folder)
    problems = []
    for component in components:
        inside = [f"    {source} -> {target} ({example[(source, target)]})" for source in component
                  for target in sorted(graph[source]) if target in component]
        problems.append("folder cycle: " + ", ".join(component) + "\n" + "\n".join(inside))
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    edges = includes(root)
    problems = unplaced_folders(edges) + upward_includes(edges) + folder_cycles(edges)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} layering problem(s) in {root}; the folder order is in docs/architecture.md")
        return 1
    print(f"layering: {len({e[2] for e in edges})} folders, {len(edges)} includes, "
          "all downward, no cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
