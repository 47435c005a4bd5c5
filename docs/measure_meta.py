"""What every docs/measure_*.py page shares: where its figures come from (the commit measured,
marked when the work tree had uncommitted changes, and the machine) and how it is written."""
import os
import platform
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SYLVA = os.path.join(ROOT, "build", "bin", "sylva")
# Trees written as glTF by `sylva plant` and read back through the importer: name, preset, seed.
IMPORTED = [("oak_hd", "broadleaf_hd", 2), ("spruce", "conifer", 5)]


def export_imported(folder, run):
    """Writes the IMPORTED trees into `folder` with `run` (a command runner); their paths."""
    paths = []
    for name, preset, seed in IMPORTED:
        path = os.path.join(folder, name + ".glb")
        run([SYLVA, "plant", preset, "--seed", str(seed), "--out", path])
        paths.append(path)
    return paths


def commit():
    c = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                           capture_output=True, text=True).stdout.strip()
    return c + (" with uncommitted changes" if dirty else "")


def machine():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def write_page(name, lines):
    """Writes docs/results/<name> from the page's lines."""
    os.makedirs(os.path.join(ROOT, "docs", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "docs", "results", name), "w") as f:
        f.write("\n".join(lines))
    print(f"wrote docs/results/{name}", file=sys.stderr)
