"""Checks that an OBJ mesh is a closed, consistently oriented 2-manifold, optionally of a given genus.

Every directed edge must appear once and its reverse once (no boundary, no fold, no non-manifold edge); with the
genus given, the Euler characteristic V - E + F must be 2 - 2g (V counts the vertices the faces use).
Usage: closed_mesh.py MESH.obj [GENUS]
"""
import collections
import sys

edges = collections.Counter()
used = set()
faces = 0
for line in open(sys.argv[1]):
    if line.startswith("f "):
        corners = [int(token.split("/")[0]) for token in line.split()[1:]]
        faces += 1
        used.update(corners)
        for a, b in zip(corners, corners[1:] + corners[:1]):
            edges[(a, b)] += 1
problems = []
if faces == 0:
    problems.append("no faces")
unmatched = sum(1 for (a, b), count in edges.items() if count != 1 or edges[(b, a)] != 1)
if unmatched:
    problems.append(f"{unmatched} directed edges without exactly one opposite")
if len(sys.argv) > 2:
    euler = len(used) - len(edges) // 2 + faces
    genus = int(sys.argv[2])
    if euler != 2 - 2 * genus:
        problems.append(f"Euler characteristic {euler}, not {2 - 2 * genus} (genus {genus})")
for problem in problems:
    print(f"{sys.argv[1]}: {problem}", file=sys.stderr)
sys.exit(1 if problems else 0)
