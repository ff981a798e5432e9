#!/usr/bin/env python3
"""The floors between the libraries, checked by the compiler.

Each library's folder may include its own headers and those of the libraries it links, as
core/CMakeLists.txt draws them (LAYERS below, which must say the same). For each library the
check makes a scratch include root holding links to exactly those folders (root/core/geom ->
<source>/core/geom, ...) and runs the C++ preprocessor over every source and header of the
library with that root alone in place of the repository: an include that crosses a floor is
"No such file or directory" there, naming the header, and fails the check. The unit tests of a
core library (tests/<library>/) are held to the same floor, with tests/support beside it.

Usage: check_layers.py --root SOURCE_DIR [--compiler CXX] [--jobs N]
           checks the tree; exit 1 and one line per crossing include when there is one
       check_layers.py --root SOURCE_DIR --self-test [--compiler CXX]
           writes scratch files with a deliberately wrong include (geom into doc, protocol into
           doc and into scene, a geom test into doc) and one allowed include (scene into doc),
           checks each as a file of its folder, and expects exactly the wrong ones to fail
           with the compiler's "No such file" for the header they name (exit 0 when they do)
"""
import argparse
import concurrent.futures
import os
import shutil
import subprocess
import sys
import tempfile

# folder -> the folders its code may include (its own first), as core/CMakeLists.txt links them.
CORE = {
    "core/geom": ["core/geom"],
    "core/json": ["core/json", "core/geom"],
    "core/exchange": ["core/exchange", "core/geom"],
    "core/doc": ["core/doc", "core/json", "core/geom"],
    "core/protocol": ["core/protocol", "core/json", "core/exchange", "core/geom"],
    "core/scene": ["core/scene", "core/doc", "core/json", "core/exchange", "core/geom"],
    "core/exchange_occt": ["core/exchange_occt", "core/exchange", "core/json", "core/geom"],
}
# core/sanitizer_build.hpp (whether the build has AddressSanitizer) is every folder's.
for allowed in CORE.values():
    allowed.append("core/sanitizer_build.hpp")
ALL_CORE = sorted(CORE) + ["core/sanitizer_build.hpp"]
LAYERS = dict(CORE)
# ui/view, ui/image and ui/figure see the core and the libraries they link, never the rest of ui.
LAYERS["ui/view"] = ["ui/view"] + ALL_CORE
LAYERS["ui/image"] = ["ui/image"] + ALL_CORE
LAYERS["ui/figure"] = ["ui/figure", "ui/view", "ui/image"] + ALL_CORE
# A core library's unit tests: that library's floor, tests/support, and the test helpers of the
# libraries it may use (tests/doc/doc_fixtures.hpp for tests/scene).
for folder, allowed in CORE.items():
    if folder != "core/exchange_occt":  # its tests read scenes back: they link the whole core
        test_folder = "tests/" + folder.split("/")[1]
        helpers = ["tests/" + a.split("/")[1] for a in allowed if a.count("/") == 1]
        LAYERS[test_folder] = helpers + ["tests/support"] + allowed

SOURCES = (".cpp", ".hpp", ".h", ".inl")
SYSTEM = ["/usr/include/opencascade", "/usr/include/imgui", "/usr/include/stb", "/usr/include/cairo"]


def make_root(scratch, name, folders, source_dir):
    root = os.path.join(scratch, name.replace("/", "_"))
    for folder in folders:
        link = os.path.join(root, folder)
        os.makedirs(os.path.dirname(link), exist_ok=True)
        if not os.path.lexists(link):
            os.symlink(os.path.join(source_dir, folder), link)
    return root


def files_of(source_dir, folder):
    out = []
    base = os.path.join(source_dir, folder)
    for dirpath, dirnames, names in os.walk(base):
        # a folder with its own floor (ui/view inside ui) is checked as itself
        dirnames[:] = [d for d in dirnames
                       if os.path.relpath(os.path.join(dirpath, d), source_dir) not in LAYERS]
        out += [os.path.join(dirpath, n) for n in sorted(names) if n.endswith(SOURCES)]
    return sorted(out)


def preprocess(compiler, root, path):
    """The compiler's complaint about a missing header, or None when every include is found."""
    cmd = [compiler, "-std=c++20", "-x", "c++", "-E", "-o", os.devnull, "-I", root,
           "-DISOPARM_HAVE_OCCT", "-DGLM_FORCE_CXX17", "-DGLM_ENABLE_EXPERIMENTAL"]
    for s in SYSTEM:
        if os.path.isdir(s):
            cmd += ["-isystem", s]
    run = subprocess.run(cmd + [path], capture_output=True, text=True)
    if run.returncode == 0:
        return None
    lines = [l for l in run.stderr.splitlines() if "No such file" in l or "error" in l]
    return lines[0] if lines else run.stderr.strip()[:400]


def check(source_dir, compiler, jobs, layers=LAYERS, extra=(), tree=True):
    """[(file, complaint)] for every file whose includes leave its floor; extra: (file, folder)
    pairs of files outside the tree checked as files of that folder; tree: check the tree's own
    files too."""
    scratch = tempfile.mkdtemp(prefix="isoparm-layers-")
    try:
        work = []
        for folder, allowed in layers.items():
            root = make_root(scratch, folder, allowed, source_dir)
            if tree:
                work += [(f, root) for f in files_of(source_dir, folder)]
            work += [(f, root) for f, where in extra if where == folder]
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            answers = list(pool.map(lambda w: (w[0], preprocess(compiler, w[1], w[0])), work))
        return len(work), [(f, c) for f, c in answers if c]
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def self_test(source_dir, compiler):
    cases = [  # (folder the scratch file is checked as, the header it includes, should fail)
        ("core/geom", "core/doc/document.hpp", True),
        ("core/protocol", "core/doc/document.hpp", True),
        ("core/protocol", "core/scene/scene_io.hpp", True),
        ("core/json", "core/exchange/mesh_weld.hpp", True),
        ("tests/geom", "core/json/fields.hpp", True),
        ("core/scene", "core/doc/document.hpp", False),
        ("core/doc", "core/geom/types.hpp", False),
    ]
    scratch = tempfile.mkdtemp(prefix="isoparm-layers-probe-")
    try:
        extra, expect = [], {}
        for k, (folder, header, fails) in enumerate(cases):
            path = os.path.join(scratch, f"probe{k}.cpp")
            with open(path, "w") as f:
                f.write(f'#include "{header}"\n')
            extra.append((path, folder))
            expect[path] = (folder, header, fails)
        layers = {folder: LAYERS[folder] for folder, _, _ in cases}
        # Only the probes: the real files of these folders are the main check's.
        _, failed = check(source_dir, compiler, 2, layers, extra, tree=False)
        failed = {f: c for f, c in failed if f in expect}
        ok = True
        for path, (folder, header, fails) in expect.items():
            complaint = failed.get(path)
            right = (complaint is not None and header in complaint and "No such file" in complaint
                     ) if fails else complaint is None
            verdict = "refused" if complaint else "allowed"
            print(f"{'ok  ' if right else 'FAIL'} {folder} including {header}: {verdict}"
                  + (f" ({complaint.strip()})" if complaint else ""))
            ok = ok and right
        return 0 if ok else 1
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--root", required=True)
    p.add_argument("--compiler", default=os.environ.get("CXX", "c++"))
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--self-test", action="store_true")
    a = p.parse_args()
    source_dir = os.path.abspath(a.root)
    if a.self_test:
        return self_test(source_dir, a.compiler)
    count, failed = check(source_dir, a.compiler, a.jobs)
    for f, complaint in failed:
        print(f"{os.path.relpath(f, source_dir)}: {complaint.strip()}")
    print(f"check_layers: {count} files in {len(LAYERS)} folders, "
          f"{len(failed)} include across a floor")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
