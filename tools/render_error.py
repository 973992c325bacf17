"""What the comparison tools share about image error: the isotrace they run, the RMS error of an image against a
reference, references rendered once and cached by what they depend on, and the time at which a ladder of renders
reaches a given error. Used by tools/compare-embree, tools/compare-tessellation and tools/convergence."""
import hashlib, math, os, re, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ISOTRACE = os.path.join(ROOT, os.environ.get("ISOTRACE_BUILD_DIR", "build"), "bin", "isotrace")


def rms_error(image, reference):
    """idiff's RMS error of `image` against `reference` (over the channels they share)."""
    result = subprocess.run(["idiff", "-v", image, reference], capture_output=True, text=True)
    match = re.search(r"RMS error = ([0-9.eE+-]+)", result.stdout)
    if not match:
        sys.exit(f"idiff printed no RMS error for {image}:\n{result.stdout}{result.stderr}")
    return float(match.group(1))


def scene_files(scene_path):
    """The scene file and every existing file it names (meshes, textures, includes), relative to the scene's folder
    or absolute, in a stable order: what a render of it depends on besides the build. Every string literal of the
    text is tried (scene files may hold comments, which the json module does not read)."""
    folder = os.path.dirname(os.path.abspath(scene_path))
    with open(scene_path) as f:
        text = f.read()
    found = set()
    for literal in re.findall(r'"((?:[^"\\\n]|\\.){1,4096})"', text):
        path = os.path.join(folder, literal)
        if os.path.isfile(path):
            found.add(os.path.abspath(path))
    return [os.path.abspath(scene_path)] + sorted(found)


def cached_reference(cache, files, key_text, render, channels=("R", "G", "B"), clamp=False, isotrace=None):
    """The reference image under `cache`, keyed by the contents of `files`, `key_text` and `isotrace --version`;
    when missing it is made by render(raw_exr_path), reduced to `channels` (None: all) (clamped to [0, 1] with
    `clamp`) and
    moved into place whole, so an interrupted render never leaves a half-written reference under the cached name."""
    key = hashlib.sha256()
    for path in files:
        with open(path, "rb") as f:
            key.update(f.read())
    version = subprocess.run([isotrace or ISOTRACE, "--version"], capture_output=True, text=True, check=True).stdout
    key.update(f"{key_text} {version}".encode())
    os.makedirs(cache, exist_ok=True)
    reference = os.path.join(cache, key.hexdigest()[:16] + ".exr")
    if not os.path.exists(reference):
        print(f"rendering the reference {key_text} (cached as {reference})", file=sys.stderr)
        raw = reference + ".raw.exr"
        partial = reference + ".partial.exr"
        render(raw)
        command = (["oiiotool", raw] + (["--ch", ",".join(channels)] if channels else []) +
                   (["--clamp:min=0:max=1"] if clamp else []))
        subprocess.run(command + ["-o", partial], check=True)
        os.remove(raw)
        os.replace(partial, reference)
    return reference


def interpolated_time_to_error(ladder_rows, target_error, key):
    """The time (ladder_rows[i][key]) at which the ladder's error (ladder_rows[i]["rms_error"], rungs in order of
    increasing samples) reaches target_error, on the straight line in log(time), log(error) through the two rungs
    that bracket it (error falls as a power of the time between neighbouring rungs); None when no two neighbouring
    rungs bracket it."""
    for low, high in zip(ladder_rows, ladder_rows[1:]):
        if low["rms_error"] >= target_error >= high["rms_error"] and low["rms_error"] > high["rms_error"] > 0:
            fraction = math.log(low["rms_error"] / target_error) / math.log(low["rms_error"] / high["rms_error"])
            return math.exp(math.log(low[key]) + fraction * math.log(high[key] / low[key]))
    return None
