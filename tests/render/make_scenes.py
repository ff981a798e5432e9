#!/usr/bin/env python3
"""Writes assets/scenes/*.json, the paper's figures (Zhou, Zhao, Lowther and Shene,
"Teaching Surface Design Made Easy") with the paper's numbers. Hand-made nets are literals
here; every constructed surface (knot insertion, splitting, ruled, revolution, skinning) is
computed by `isoparm geom`, so the scenes are reproducible and never edited by hand.

usage: python3 tests/render/make_scenes.py [--isoparm build/app/isoparm] [--out assets/scenes]
Standard library only.
"""

import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# The paper's knot vector for 5 control points of degree 3: 0^4 0.5 1^4 (Figures 3 to 6).
KNOTS_5_3 = [0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]

# Figure 8: 11 points, degree 3, 15 uniformly spaced knots clamped at both ends
# (0^4, the 7 interior knots k/8, 1^4).
KNOTS_11_3 = [0.0] * 4 + [k / 8 for k in range(1, 8)] + [1.0] * 4

# The full NURBS circle: 9 control points on the square, quadratic, weights 1 and sqrt(2)/2
# at the square's corners (Piegl & Tiller 7.5).
HALF_SQRT2 = 0.7071067811865476
CIRCLE_KNOTS = [0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0]
CIRCLE_UNIT = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
CIRCLE_WEIGHTS = [1.0, HALF_SQRT2] * 4 + [1.0]


def geom(isoparm, request):
    """One `isoparm geom` request; its response, or exit with the error."""
    proc = subprocess.run([isoparm, "geom"], input=json.dumps(request), capture_output=True,
                          text=True, check=False)
    if proc.returncode != 0:
        sys.exit(f"make_scenes: isoparm geom {request['op']} failed ({proc.returncode}): "
                 f"{proc.stdout.strip()} {proc.stderr.strip()}")
    response = json.loads(proc.stdout)
    assert response.get("ok") is True, response
    return response


def grid_net(heights, half=1.0):
    """A 5x5 net over [-half, half]^2 (the Surface > New grid) with the given heights."""
    n = len(heights)
    return [[[(2.0 * i - (n - 1)) / (n - 1) * half, (2.0 * j - (n - 1)) / (n - 1) * half,
              float(heights[i][j])] for j in range(n)] for i in range(n)]


def nurbs_surface(points, weights=None, surface_type="nurbs"):
    s = {"type": surface_type, "degree": [3, 3], "knots": [KNOTS_5_3, KNOTS_5_3], "points": points}
    if surface_type in ("nurbs", "rational_bezier"):
        s["weights"] = weights or [[1.0] * len(points[0]) for _ in points]
    return s


def surface_object(oid, name, surface, patch_group=None, construction=None):
    o = {"id": oid, "name": name, "kind": "surface", "surface": surface}
    if patch_group is not None:
        o["patch_group"] = patch_group
    if construction is not None:
        o["construction"] = construction
    return o


def curve_object(oid, name, curve, plane):
    return {"id": oid, "name": name, "kind": "curve", "plane": plane, "curve": curve}


def scene(objects, display, selection=None, indicator=(0.5, 0.5)):
    full_display = {"style": "both", "control_points": True, "control_net": True,
                    "point_ids": False, "knot_curves": False, "indicator_point": True,
                    "deboor": False, "density": 32}
    full_display.update(display)
    # Version 2 where an object keeps its construction (docs/scene-format.md).
    version = 2 if any("construction" in o for o in objects) else 1
    return {"format": "isoparm-scene", "version": version, "objects": objects,
            "selection": selection, "indicator": list(indicator), "display": full_display}


# --- the nets -------------------------------------------------------------------------------

# Figure 3: P22 is the peak of the control net.
HILL = [[0.0, 0.1, 0.2, 0.1, 0.0],
        [0.1, 0.3, 0.4, 0.3, 0.1],
        [0.2, 0.4, 1.2, 0.4, 0.2],
        [0.1, 0.3, 0.4, 0.3, 0.1],
        [0.0, 0.1, 0.2, 0.1, 0.0]]

# Figures 5 and 6: an asymmetric, wavy patch so that the knot curves and the pieces show.
WAVE = [[0.0, 0.3, 0.5, 0.3, 0.0],
        [0.2, 0.8, 0.4, -0.2, -0.3],
        [0.3, 0.6, 0.0, -0.5, -0.4],
        [0.1, 0.2, -0.2, 0.1, 0.3],
        [-0.1, 0.0, 0.2, 0.6, 0.8]]


def shaped_net():
    """Figure 2(b): the flat grid after dragging points in all directions (x, y and z)."""
    net = grid_net([[0.0] * 5 for _ in range(5)])
    moves = {(0, 0): (0.0, 0.0, 0.5), (0, 4): (0.0, 0.0, -0.3), (1, 1): (0.0, 0.0, 0.7),
             (1, 3): (0.1, 0.0, 0.4), (2, 2): (0.0, 0.0, -0.6), (2, 0): (-0.2, 0.0, 0.3),
             (3, 1): (0.0, -0.1, -0.4), (3, 3): (0.0, 0.0, 0.8), (4, 2): (0.15, 0.0, 0.4),
             (4, 4): (0.0, 0.0, 0.3)}
    for (i, j), (dx, dy, dz) in moves.items():
        p = net[i][j]
        net[i][j] = [p[0] + dx, p[1] + dy, p[2] + dz]
    return net


# --- the scenes -----------------------------------------------------------------------------

def figure_scenes(isoparm):
    scenes = {}
    flat = nurbs_surface(grid_net([[0.0] * 5 for _ in range(5)]), surface_type="bspline")
    scenes["fig2a-flat-grid"] = scene([surface_object(1, "grid", flat)], {},
                                      selection={"object": 1})
    shaped = nurbs_surface(shaped_net(), surface_type="bspline")
    scenes["fig2b-shaped"] = scene([surface_object(1, "grid", shaped)], {},
                                   selection={"object": 1, "point": [3, 3]})

    # Figure 3: w22 = 1 (a B-spline surface written as NURBS), 5 and 0.3; P22 selected.
    for name, w in (("fig3a-bspline", 1.0), ("fig3b-weight-5", 5.0), ("fig3c-weight-0.3", 0.3)):
        weights = [[1.0] * 5 for _ in range(5)]
        weights[2][2] = w
        hill = nurbs_surface(grid_net(HILL), weights)
        scenes[name] = scene([surface_object(1, "hill", hill)], {},
                             selection={"object": 1, "point": [2, 2]})

    # Figure 4: every step of de Boor's algorithm at (u, v) = (0.3, 0.6).
    hill = nurbs_surface(grid_net(HILL))
    scenes["fig4-deboor"] = scene([surface_object(1, "hill", hill)],
                                  {"deboor": True, "style": "wireframe"},
                                  selection={"object": 1}, indicator=(0.3, 0.6))

    # Figure 5: knot curves for 0^4 0.5 1^4 in both directions, then 0.75 inserted in u.
    wave = nurbs_surface(grid_net(WAVE))
    # The indicator is off: at its default (0.5, 0.5) its isocurves would hide the knot curves.
    knot_display = {"knot_curves": True, "indicator_point": False}
    scenes["fig5a-knot-curves"] = scene([surface_object(1, "wave", wave)], knot_display,
                                        selection={"object": 1})
    inserted = geom(isoparm, {"op": "insert_knot", "surface": wave, "direction": "u",
                              "knot": 0.75})["surface"]
    scenes["fig5b-knot-inserted"] = scene([surface_object(1, "wave", inserted)], knot_display,
                                          selection={"object": 1})
    # Degree elevation in u (3 to 4): the same shape on a denser net.
    elevated = geom(isoparm, {"op": "elevate_degree", "surface": wave, "direction": "u",
                              "times": 1})["surface"]
    scenes["fig5c-degree-elevated"] = scene([surface_object(1, "wave", elevated)], knot_display,
                                            selection={"object": 1})
    # A knot dragged in the tracing panel: v = 0.5 moved to 0.3 (the knot curve follows and
    # the shape changes, unlike insertion and elevation).
    moved = json.loads(json.dumps(wave))
    moved["knots"][1][4] = 0.3
    scenes["fig5d-knot-moved"] = scene([surface_object(1, "wave", moved)], knot_display,
                                       selection={"object": 1})

    # Figure 6: split at u = 0.75, then the left piece at v = 0.5 (pieces keep their part of
    # the domain; names follow the workstation's <name>.1, <name>.2).
    left, right = geom(isoparm, {"op": "split", "surface": wave, "direction": "u",
                                 "param": 0.75})["pieces"]
    # The pieces form patch group 1: the tracing square keeps showing the whole original
    # domain and the indicator picks the current patch.
    scenes["fig6b-split-u075"] = scene(
        [surface_object(1, "wave.1", left, 1), surface_object(2, "wave.2", right, 1)],
        {"knot_curves": True}, selection={"object": 1}, indicator=(0.3, 0.5))
    low, high = geom(isoparm, {"op": "split", "surface": left, "direction": "v",
                               "param": 0.5})["pieces"]
    # With continuity C1 the workstation's second split also refines the right part at
    # v = 0.5 up to its degree, so every border pairs up control point for control point.
    conforming_right = geom(isoparm, {"op": "insert_knot", "surface": right, "direction": "v",
                                      "knot": 0.5, "times": 2})["surface"]
    scenes["fig6c-split-left-v05"] = scene(
        [surface_object(1, "wave.1.1", low, 1), surface_object(2, "wave.1.2", high, 1),
         surface_object(3, "wave.2", conforming_right, 1)],
        {"knot_curves": True}, selection={"object": 1}, indicator=(0.3, 0.25))
    scenes["fig6c-split-left-v05"]["continuity"] = "C1"

    # Figure 7: two unit circles at z = -1 and z = 1, the lower one rotated by 90 degrees
    # ((x, y) -> (-y, x), exact); the ruled surface between them is a hyperboloid of one
    # sheet x^2 + y^2 - z^2/2 = 1/2 (docs/constructions.md, alpha = 90 degrees).
    def circle(z, rotate):
        pts = [[-y, x, z] if rotate else [x, y, z] for (x, y) in CIRCLE_UNIT]
        pts = [[float(c) + 0.0 for c in p] for p in pts]  # + 0.0: no -0.0 in the file
        return {"type": "nurbs", "degree": 2, "knots": CIRCLE_KNOTS, "points": pts,
                "weights": CIRCLE_WEIGHTS}
    lower, upper = circle(-1.0, True), circle(1.0, False)
    ruled = geom(isoparm, {"op": "ruled", "curves": [lower, upper]})["surface"]
    scenes["fig7-hyperboloid"] = scene(
        [surface_object(1, "hyperboloid", ruled,
                        construction={"operation": "ruled", "inputs": [2, 3]}),
         curve_object(2, "lower circle", lower, "free3d"),
         curve_object(3, "upper circle", upper, "free3d")],
        {"control_points": False}, selection={"object": 1})

    # Figure 8: an 11-point degree-3 profile in the xz-plane, revolved about z. The vase keeps
    # its recipe: `move_curve_point` on the profile moves the vase's control points with it.
    profile_xz = [(0.0, 0.0), (0.9, 0.0), (1.1, 0.25), (0.7, 0.6), (0.4, 1.0), (0.35, 1.4),
                  (0.5, 1.8), (0.9, 2.1), (1.0, 2.5), (0.8, 2.8), (0.75, 3.0)]
    profile = {"type": "bspline", "degree": 3, "knots": KNOTS_11_3,
               "points": [[x, 0.0, z] for (x, z) in profile_xz]}
    revolved = geom(isoparm, {"op": "revolve", "curve": profile})["surface"]
    scenes["fig8-revolution"] = scene(
        [surface_object(1, "vase", revolved,
                        construction={"operation": "revolve", "inputs": [2], "angle": 360.0}),
         curve_object(2, "profile", profile, "xz")],
        {"control_points": False, "control_net": False}, selection={"object": 2})

    # Figure 9: four degree-3 NURBS sections (y = -1.5 .. 1.5, different knots and counts, so
    # skinning makes them compatible first) skinned with v-degree 3. Unit weights: sections
    # with different weight patterns are interpolated in homogeneous space, which gives the
    # net negative weights and far-away points (right, but unreadable as a figure).
    sections = [
        {"type": "nurbs", "degree": 3, "knots": KNOTS_5_3,
         "points": [[-1.0, -1.5, 0.0], [-1.0, -1.5, 0.6], [0.0, -1.5, 0.9], [1.0, -1.5, 0.6],
                    [1.0, -1.5, 0.0]],
         "weights": [1.0, 1.0, 1.0, 1.0, 1.0]},
        {"type": "nurbs", "degree": 3, "knots": [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
         "points": [[-1.3, -0.5, 0.0], [-1.2, -0.5, 1.3], [1.2, -0.5, 1.3], [1.3, -0.5, 0.0]],
         "weights": [1.0, 1.0, 1.0, 1.0]},
        {"type": "nurbs", "degree": 3, "knots": [0.0, 0.0, 0.0, 0.0, 0.4, 0.6, 1.0, 1.0, 1.0,
                                                 1.0],
         "points": [[-1.2, 0.5, 0.0], [-1.3, 0.5, 0.8], [-0.5, 0.5, 1.2], [0.5, 0.5, 1.2],
                    [1.3, 0.5, 0.8], [1.2, 0.5, 0.0]],
         "weights": [1.0, 1.0, 1.0, 1.0, 1.0, 1.0]},
        {"type": "nurbs", "degree": 3, "knots": KNOTS_5_3,
         "points": [[-0.8, 1.5, 0.0], [-0.8, 1.5, 0.4], [0.0, 1.5, 0.5], [0.8, 1.5, 0.4],
                    [0.8, 1.5, 0.0]],
         "weights": [1.0, 1.0, 1.0, 1.0, 1.0]},
    ]
    skinned = geom(isoparm, {"op": "skin", "curves": sections, "degree": 3})["surface"]
    # The recipe keeps the skin linked to its sections: moving a section rebuilds it.
    objects = [surface_object(1, "skin", skinned,
                              construction={"operation": "skin", "inputs": [2, 3, 4, 5],
                                            "degree": 3, "parametrization": "chord"})]
    objects += [curve_object(2 + k, f"section {k + 1}", c, "free3d")
                for k, c in enumerate(sections)]
    scenes["fig9-skinned"] = scene(objects, {"control_points": False, "control_net": False},
                                   selection={"object": 1})

    # The paper's future work: a rational cubic triangular Bezier patch (Farin ch. 17), the
    # flat triangle of Surface > New triangular patch with its middle point b111 lifted and
    # weighted 2, the edge points b210 and b120 raised and b012 lowered.
    scenes["triangle-cubic"] = triangle_scene()

    # Trimming by a projected curve (issue #35): Figure 3(b)'s hill and a circle of radius 0.5
    # drawn in the xy plane under it, for Surface > Trim > Cut a hole along a curve.
    hill = nurbs_surface(grid_net(HILL), [[5.0 if (i, j) == (2, 2) else 1.0 for j in range(5)]
                                          for i in range(5)])
    cutter = {"type": "nurbs", "degree": 2, "knots": CIRCLE_KNOTS,
              "points": [[0.25 + 0.5 * x, 0.5 * y, 0.0] for (x, y) in CIRCLE_UNIT],
              "weights": CIRCLE_WEIGHTS}
    scenes["trim-by-curve"] = scene([surface_object(1, "hill", hill),
                                     curve_object(2, "cutter", cutter, "xy")], {},
                                    selection={"object": 1})
    return scenes


def triangle_scene():
    corners = [(2.0, 0.0, 0.0), (-1.0, 3 ** 0.5, 0.0), (-1.0, -(3 ** 0.5), 0.0)]
    heights = {(1, 1, 1): 1.5, (2, 1, 0): 0.5, (1, 2, 0): 0.5, (0, 1, 2): -0.4}
    points, weights = [], []
    n = 3
    for i in range(n, -1, -1):  # the protocol's order: b_n00 first, b_00n last
        for j in range(n - i, -1, -1):
            k = n - i - j
            p = [round((i * corners[0][a] + j * corners[1][a] + k * corners[2][a]) / n, 4)
                 for a in range(3)]
            p[2] = heights.get((i, j, k), 0.0)
            points.append(p)
            weights.append(2.0 if (i, j, k) == (1, 1, 1) else 1.0)
    triangle = {"type": "rational_triangle_bezier", "degree": n, "points": points,
                "weights": weights}
    content = scene([{"id": 1, "name": "dome", "kind": "triangle", "triangle": triangle}], {},
                    selection={"object": 1, "point": [1, 1]})
    content["barycentric"] = [0.25, 0.25, 0.5]
    return content


# --- writing --------------------------------------------------------------------------------

def dump(value, indent=0):
    """JSON with numbers in shortest round-trip form (Python's repr), one point or one short
    number array per line, so the scenes read like the paper's tables."""
    pad, inner = "  " * indent, "  " * (indent + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = [f"{inner}{json.dumps(k)}: {dump(v, indent + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list):
        flat = all(not isinstance(v, (dict, list)) for v in value)
        if flat or all(isinstance(v, list) and all(not isinstance(x, (dict, list)) for x in v)
                       for v in value) and len(value) <= 12 and len(json.dumps(value)) <= 90:
            return json.dumps(value)
        items = [inner + dump(v, indent + 1) for v in value]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(value)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--isoparm", default=os.path.join(ROOT, "build", "app", "isoparm"))
    ap.add_argument("--out", default=os.path.join(ROOT, "assets", "scenes"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, content in figure_scenes(args.isoparm).items():
        path = os.path.join(args.out, name + ".json")
        with open(path, "w", encoding="utf-8") as f:
            f.write(dump(content) + "\n")
        print(path)


if __name__ == "__main__":
    main()
