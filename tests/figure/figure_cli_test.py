#!/usr/bin/env python3
"""`isoparm figure` and `isoparm animate` as a user runs them.

Every 2D view and the 3D view are written as SVG, PDF, TikZ and PNG from the example scenes:
- each SVG is parsed as XML and holds what its view must (one path per basis function, the
  labels as <text> elements);
- each PDF is read back by poppler's pdftotext, which must find the labels;
- each TikZ picture is compiled by pdflatex where TeX with TikZ is installed (else skipped,
  said so);
- refusals (unknown extension, a view the scene cannot show) write nothing.
A four-step script is animated to GIF and MP4 and read back with FFmpeg's decoders
(video_probe): the frame count and size must be what was asked.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(args, expect=0):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != expect:
        print(" ".join(args), "->", p.returncode, p.stderr.strip())
    return p


def png_rgba(path):
    """Width, height and RGBA rows of a PNG as isoparm writes it (8-bit RGBA, filter 0)."""
    import struct
    import zlib
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, w, h = 8, b"", 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    rows = [raw[r * (4 * w + 1) + 1:(r + 1) * (4 * w + 1)] for r in range(h)]
    return w, h, rows


def svg_texts(root):
    """The plain text of every <text> element, scripts included ("N0,3")."""
    return ["".join(t.itertext()) for t in root.iter(SVG + "text")]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--isoparm", required=True)
    ap.add_argument("--probe", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    scenes = os.path.join(a.source, "assets", "scenes")
    iso = a.isoparm

    # The basis view of fig3a: one path per basis function, labels N_{i,3} as text.
    with open(os.path.join(scenes, "fig3a-bspline.json")) as f:
        scene = json.load(f)
    surface = scene["objects"][0]["surface"]
    degree = surface["degree"][0] if isinstance(surface["degree"], list) else surface["degree"]
    n_u = len(surface["knots"][0]) - degree - 1
    cases = [
        ("fig3a-bspline.json", "basis"),
        ("fig3b-weight-5.json", "tracing"),
        ("curve-designer.json", "curve"),
        ("curve-designer.json", "deboor"),
        ("curve-designer.json", "homogeneous"),
        ("curve-designer.json", "blossom"),
        ("fig5a-knot-curves.json", "3d"),
    ]
    pdftotext = shutil.which("pdftotext")
    check(pdftotext is not None, "pdftotext (poppler-utils) is installed")
    tex = shutil.which("pdflatex")
    tikz = tex and subprocess.run(["kpsewhich", "tikz.sty"], capture_output=True,
                                  text=True).stdout.strip()
    if not tikz:
        print("skipped: the TikZ compile checks (no pdflatex with tikz.sty here)")

    for scene_name, view in cases:
        base = os.path.join(a.work, view)
        src = os.path.join(scenes, scene_name)
        for ext in ("svg", "pdf", "tex", "png"):
            out = f"{base}.{ext}"
            if os.path.exists(out):
                os.remove(out)
            p = run([iso, "figure", src, "--view", view, "-o", out])
            check(p.returncode == 0 and os.path.getsize(out) > 0, f"{view}.{ext} written")

        root = ET.parse(base + ".svg").getroot()  # raises on malformed XML
        check(root.tag == SVG + "svg", f"{view}.svg is an SVG document")
        texts = svg_texts(root)
        paths = root.findall(f".//{SVG}path")
        if view != "3d":  # the 3D view's lines carry no labels
            check(len(texts) >= 3, f"{view}.svg has its labels as <text> ({len(texts)})")
        check(len(paths) >= 3, f"{view}.svg has paths ({len(paths)})")
        if view == "basis":
            basis = [p for p in paths if p.get("class") == "basis"]
            check(len(basis) == n_u, f"basis.svg: one path per basis function "
                                     f"({len(basis)} of {n_u})")
            for i in range(n_u):
                check(f"N{i},{degree}" in texts, f"basis.svg labels N{i},{degree} as text")
            check(any(p.get("class") == "partition-of-unity" for p in paths),
                  "basis.svg draws the partition of unity")
        if view == "tracing":
            check(any("(u, v) = (" in t for t in texts), "tracing.svg labels the indicator")
            check(any(t.startswith("w22 = 5") for t in texts), "tracing.svg labels w22 = 5")
        if view == "deboor":
            check(sum(1 for t in texts if t.startswith("d")) >= 3,
                  "deboor.svg labels the intermediate points d^k_i")
        if view == "3d":
            check(root.find(f".//{SVG}image") is not None, "3d.svg has the shaded raster")
            check(any((p.get("class") or "").startswith("net") for p in paths),
                  "3d.svg has the control net as vector paths")

        if pdftotext:
            text = subprocess.run([pdftotext, base + ".pdf", "-"], capture_output=True,
                                  text=True).stdout
            want = {"basis": [f"N0,{degree}", "sum of all = 1", "U = {"], "tracing": ["(u, v) ="],
                    "curve": ["P0", "C(", "T", "N"], "deboor": ["construction", "C(t)"],
                    "homogeneous": ["w = 1"], "blossom": ["f(t, t, t)"],
                    "3d": []}[view]
            for w in want:
                check(w in text, f"pdftotext finds '{w}' in {view}.pdf")
        if tikz:
            doc = os.path.join(a.work, f"{view}-doc.tex")
            with open(doc, "w") as f:
                f.write("\\documentclass{article}\\pagestyle{empty}\n\\usepackage{tikz}\n\\usepackage{graphicx}\n"
                        f"\\begin{{document}}\n\\input{{{view}.tex}}\n\\end{{document}}\n")
            p = subprocess.run([tex, "-interaction=nonstopmode", "-halt-on-error",
                                os.path.basename(doc)], cwd=a.work, capture_output=True,
                               text=True)
            check(p.returncode == 0, f"{view}.tex compiles with pdflatex")

    # A transparent picture: alpha 0 where the background was, opaque on the surface.
    out = os.path.join(a.work, "transparent.png")
    p = run([iso, "render", os.path.join(scenes, "fig8-revolution.json"), "--view", "3d",
             "--size", "160x120", "--transparent", "-o", out])
    w, h, rows = png_rgba(out)
    check(p.returncode == 0 and rows[2][4 * 150 + 3] == 0 and rows[60][4 * 80 + 3] == 255,
          "render --transparent: the corner is transparent, the vase opaque")

    # Refusals write nothing.
    bad = os.path.join(a.work, "refused.odt")
    p = run([iso, "figure", os.path.join(scenes, "fig3a-bspline.json"), "--view", "basis",
             "-o", bad], expect=2)
    check(p.returncode == 2 and not os.path.exists(bad) and ".svg" in p.stderr,
          "an unknown extension is refused, naming the ones known")
    bad = os.path.join(a.work, "refused.svg")
    p = run([iso, "figure", os.path.join(scenes, "implicit-gallery.json"), "--view", "tracing",
             "-o", bad], expect=2)
    check(p.returncode == 2 and not os.path.exists(bad) and "needs a surface" in p.stderr,
          "a view the scene cannot show is refused with the reason")

    # A four-step script: the start and four pictures, each held 2 frames.
    script = os.path.join(a.source, "tests", "figure", "four-steps.json")
    for ext, codec in (("gif", "gif"), ("mp4", "h264")):
        out = os.path.join(a.work, f"four-steps.{ext}")
        if os.path.exists(out):
            os.remove(out)
        p = run([iso, "animate", script, "-o", out, "--size", "320x200", "--fps", "8",
                 "--step-frames", "2"])
        check(p.returncode == 0, f"animate four-steps.{ext}")
        probe = run([a.probe, out])
        fields = probe.stdout.split()
        check(probe.returncode == 0 and fields[:4] == ["10", "320", "200", codec],
              f"four-steps.{ext} reads back as 10 frames of 320x200 {codec} ({probe.stdout.strip()})")
    # A sequence from a scene: de Boor's 8 steps of a bicubic (0 .. p_u + p_v + 1).
    out = os.path.join(a.work, "deboor.gif")
    p = run([iso, "animate", os.path.join(scenes, "fig4-deboor.json"), "--deboor", "-o", out,
             "--size", "320x200"])
    probe = run([a.probe, out])
    check(p.returncode == 0 and probe.stdout.split()[:3] == ["8", "320", "200"],
          f"de Boor's steps of a bicubic: 8 frames ({probe.stdout.strip()})")
    # Refusals: an odd MP4 size, a scene without a sequence; nothing written.
    out = os.path.join(a.work, "odd.mp4")
    p = run([iso, "animate", script, "-o", out, "--size", "321x200"], expect=2)
    check(p.returncode == 2 and "even" in p.stderr and not os.path.exists(out),
          "an odd MP4 size is refused")
    p = run([iso, "animate", os.path.join(scenes, "fig4-deboor.json"), "-o", out], expect=2)
    check(p.returncode == 2 and "--deboor" in p.stderr and not os.path.exists(out),
          "a scene alone is refused, naming the sequences")

    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
