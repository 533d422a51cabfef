#!/usr/bin/env python3
"""Writes data/tasks/: realistic task specs as a robotics engineer would write them for real cells
(grasps, welding, assembly, painting/dispensing, inspection, deburring, screwdriving,
palletizing), issue 16 deliverable 5, and data/tasks/expected.json.

Every feasible task is built around a valid pose X* of the mobile object, chosen first: the
features and the values/ranges are then written so that every constraint holds at X* (a range
with X*'s value strictly inside it). X* is not in the spec: the spec's mobile pose is the robot's
current pose, a few centimetres and some tens of degrees away from X*. This script checks every
constraint of every feasible task at X*, with the semantics of docs/spec.md section 1.9, and
fails loudly when one is violated (beyond 1e-9) or sits within 1% of a range bound. The
deliberately infeasible tasks say why no pose exists; a small penalty minimisation from many
starts double-checks that it finds none.

expected.json: {name: {"feasible": bool, "pose": {"position": [m], "rpy": [deg]} (feasible only),
"why": "..."}}; rpy is fixed axes X, Y, Z (R = Rz(yaw) Ry(pitch) Rx(roll)) in degrees, as in the
specs.

Usage: scripts/make_task_specs.py [--check-relpos BUILD/cli/relpos]
  --check-relpos runs every spec through relpos and prints its status; for a solved feasible
  task it also solves a copy whose mobile pose is X* (in a temporary folder) and reports whether
  a branch contains X* (nearest distance ~ 0), and it checks every branch's nearest pose against
  this script's own constraint evaluator.
Standard library only; the output is deterministic.
"""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "data", "tasks")

EXACT_TOL = 1e-9       # an exact constraint at X*: residual at most this (m or rad)
BOUND_MARGIN = 0.01    # a range value at X*: at least 1% of the range's width from each bound

# ---------------------------------------------------------------------------------------------
# Small vector / rotation helpers (3-vectors are lists, rotations 3x3 row-major lists).


def add(a, b): return [a[i] + b[i] for i in range(3)]
def sub(a, b): return [a[i] - b[i] for i in range(3)]
def scale(a, s): return [a[i] * s for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return scale(a, 1.0 / norm(a))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def mat_vec(R, v): return [dot(R[i], v) for i in range(3)]
def transpose(R): return [[R[j][i] for j in range(3)] for i in range(3)]


def mat_mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def angle_between(u, v):
    """The angle between two vectors, in radians, through atan2 (as relpos computes it)."""
    return math.atan2(norm(cross(u, v)), dot(u, v))


def rot_x(a):
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return [[1, 0, 0], [0, c, -s], [0, s, c]]


def rot_y(a):
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return [[c, 0, s], [0, 1, 0], [-s, 0, c]]


def rot_z(a):
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def rpy(r, p, y):
    """R = Rz(yaw) Ry(pitch) Rx(roll), angles in degrees (docs/spec.md section 1.4)."""
    return mat_mul(rot_z(y), mat_mul(rot_y(p), rot_x(r)))


def to_rpy(R):
    """The rpy angles (degrees) of a rotation; at pitch +-90 deg the yaw is taken as 0."""
    sp = max(-1.0, min(1.0, -R[2][0]))
    if abs(sp) > 1.0 - 1e-12:
        return [math.degrees(math.atan2(-R[1][2], R[1][1])), math.copysign(90.0, sp), 0.0]
    return [math.degrees(math.atan2(R[2][1], R[2][2])), math.degrees(math.asin(sp)),
            math.degrees(math.atan2(R[1][0], R[0][0]))]


def axis_angle(axis, deg):
    """Rotation about a unit axis (Rodrigues), angle in degrees."""
    k = unit(axis)
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    K2 = mat_mul(K, K)
    return [[(1 if i == j else 0) + s * K[i][j] + (1 - c) * K2[i][j] for j in range(3)]
            for i in range(3)]


def rotation_angle(R):
    """The angle (degrees) of a rotation matrix."""
    tr = R[0][0] + R[1][1] + R[2][2]
    return math.degrees(math.acos(max(-1.0, min(1.0, (tr - 1) / 2))))


def frame(z, x):
    """The rotation whose local z axis goes to world direction z and local x to the part of x
    orthogonal to z (columns x, y, z)."""
    z = unit(z)
    x = unit(sub(x, scale(z, dot(x, z))))
    y = cross(z, x)
    return [[x[i], y[i], z[i]] for i in range(3)]


class Pose:
    def __init__(self, R, t):
        self.R, self.t = R, list(t)

    def point(self, p): return add(mat_vec(self.R, p), self.t)
    def vector(self, d): return mat_vec(self.R, d)
    def then(self, other):   # self composed with other: world <- self <- other
        return Pose(mat_mul(self.R, other.R), self.point(other.t))


def pose_rpy(position, angles): return Pose(rpy(*angles), position)


def place(R, local_point, world_point):
    """The pose with rotation R that puts a point of the mobile frame at a given world point."""
    return Pose(R, sub(world_point, mat_vec(R, local_point)))


# ---------------------------------------------------------------------------------------------
# Spec building.


def pt(x, y, z): return {"point": [x, y, z]}
def line(p, d): return {"line": {"point": p, "direction": d}}
def plane(p, n): return {"plane": {"point": p, "normal": n}}
def cyl(p, d, r): return {"cylinder": {"point": p, "direction": d, "radius": r}}


def con(kind, fixed, mobile, ident, **kw):
    c = {"type": kind, "fixed": fixed, "mobile": mobile}
    c.update(kw)
    c["id"] = ident
    return c


def r7(x):
    """A computed coordinate as an engineer would type it (7 decimals)."""
    return round(x, 7) + 0.0


TASKS = []   # (spec, xstar Pose or None, why, fixed Pose used to place X* ...)


def task(name, why, fixed_name, fixed_features, mobile_name, mobile_features, constraints,
         xstar=None, near=None, fixed_pose=None):
    """Registers a task. xstar: the valid pose (world) for a feasible task, None for an
    infeasible one (then `near` is a plausible pose the robot's current pose is drawn around).
    fixed_pose: (position, rpy) of the fixed object, or None for the identity."""
    fixed = {"name": fixed_name}
    if fixed_pose is not None:
        fixed["pose"] = {"position": list(fixed_pose[0]), "rpy": list(fixed_pose[1])}
    fixed["features"] = fixed_features
    spec = {"relpos": 1, "name": name, "units": {"length": "m", "angle": "deg"},
            "fixed": fixed,
            "mobile": {"name": mobile_name, "pose": None, "features": mobile_features},
            "constraints": constraints}
    base = xstar if xstar is not None else near
    spec["mobile"]["pose"] = current_pose(name, base)
    TASKS.append((spec, xstar, why))


def fixed_pose_of(spec):
    p = spec["fixed"].get("pose")
    if p is None:
        return Pose(rpy(0, 0, 0), [0, 0, 0])
    return pose_rpy(p["position"], p["rpy"])


def current_pose(name, base):
    """The robot's current pose: X* (or `near`) moved 6-18 cm and turned 12-35 deg about a
    random axis, rounded to mm and whole degrees; checked to stay 5-20 cm and 10-40 deg away."""
    rng = random.Random("relpos-task:" + name)
    for _ in range(100):
        d = unit([rng.gauss(0, 1) for _ in range(3)])
        axis = [rng.gauss(0, 1) for _ in range(3)]
        t = add(base.t, scale(d, rng.uniform(0.06, 0.18)))
        R = mat_mul(base.R, axis_angle(axis, rng.uniform(12, 35)))
        pos = [round(v, 3) + 0.0 for v in t]
        ang = [float(round(a)) + 0.0 for a in to_rpy(R)]
        Rr = rpy(*ang)
        dist = norm(sub(pos, base.t))
        turn = rotation_angle(mat_mul(transpose(base.R), Rr))
        if 0.05 <= dist <= 0.2 and 10 <= turn <= 40:
            return {"position": pos, "rpy": ang}
    raise SystemExit(f"{name}: no current pose drawn")


# ---------------------------------------------------------------------------------------------
# Evaluation of the constraints (docs/spec.md section 1.9) at a pose of the mobile object.


class Feat:
    def __init__(self, kind, p=None, d=None, r=None):
        self.kind, self.p, self.d, self.r = kind, p, d, r


def world_feature(features, name, pose):
    axis = name.endswith(".axis")
    f = features[name[:-5] if axis else name]
    if "point" in f:
        return Feat("point", pose.point(f["point"]))
    kind = next(iter(f))
    g = f[kind]
    p = pose.point(g["point"])
    d = unit(pose.vector(g.get("direction") or g.get("normal")))
    if kind == "cylinder":
        return Feat("line", p, d) if axis else Feat("cylinder", p, d, g["radius"])
    return Feat(kind, p, d)


def point_line(p, L): return norm(cross(sub(p, L.p), L.d))
def point_plane(p, P): return dot(sub(p, P.p), P.d)


def orient_angle(m, f, orientation):
    if orientation == "opposed":
        return angle_between(m, scale(f, -1))
    if orientation == "either":
        return min(angle_between(m, f), angle_between(m, scale(f, -1)))
    return angle_between(m, f)


def skew_distance(A, B):
    n = cross(A.d, B.d)
    if norm(n) < 1e-12:
        return point_line(B.p, A)
    return abs(dot(sub(B.p, A.p), n)) / norm(n)


def evaluate(c, F, M):
    """(residuals of the exact parts, measured value or None, value kind 'length'/'angle')."""
    t, o = c["type"], c.get("orientation", "aligned")
    kinds = {F.kind, M.kind}
    res, val, vk = [], None, "length"

    def other(k):
        return F if M.kind == k else M

    if t in ("distance", "coincident"):
        if "point" in kinds:
            P = F if F.kind == "point" else M
            X = M if P is F else F
            if X.kind == "point":
                val = norm(sub(P.p, X.p))
            elif X.kind == "line":
                val = point_line(P.p, X)
            elif X.kind == "plane":
                val = point_plane(P.p, X)
            else:  # point on a cylinder (coincident only)
                res.append(point_line(P.p, X) - X.r)
                return res, None, vk
        elif F.kind == "line" and M.kind == "line":
            if t == "distance" and c.get("parallel", True) is False:
                val = skew_distance(F, M)
            else:
                res.append(orient_angle(M.d, F.d, o))
                val = point_line(M.p, F)
        elif kinds == {"line", "plane"}:
            L, P = (F, M) if F.kind == "line" else (M, F)
            res.append(math.asin(min(1.0, abs(dot(L.d, P.d)))))
            val = point_plane(L.p, P)
        elif F.kind == "plane" and M.kind == "plane":
            res.append(orient_angle(M.d, F.d, o))
            val = dot(sub(M.p, F.p), F.d)
        else:
            raise ValueError(f"{t} {F.kind}-{M.kind}")
        if t == "coincident":
            res.append(val)
            val = None
        return res, val, vk
    if t == "angle":
        if kinds == {"line", "plane"}:
            L, P = (F, M) if F.kind == "line" else (M, F)
            return res, math.pi / 2 - angle_between(L.d, P.d), "angle"
        return res, angle_between(F.d, M.d), "angle"
    if t == "parallel":
        if F.kind != M.kind:
            res.append(math.asin(min(1.0, abs(dot(F.d, M.d)))))
        else:
            res.append(orient_angle(M.d, F.d, o))
        return res, None, vk
    if t == "perpendicular":
        if F.kind != M.kind:
            res.append(orient_angle(M.d, F.d, o))
        else:
            res.append(math.asin(min(1.0, abs(dot(F.d, M.d)))))
        return res, None, vk
    if t == "tangent":
        if F.kind == "cylinder" and M.kind == "cylinder":
            res.append(orient_angle(M.d, F.d, "either"))
            res.append(point_line(M.p, F) - (F.r + M.r))
        elif kinds == {"cylinder", "plane"}:
            C, P = (F, M) if F.kind == "cylinder" else (M, F)
            s = point_plane(C.p, P)
            side = math.inf
            if o != "opposed":
                side = min(side, abs(s + C.r))
            if o != "aligned":
                side = min(side, abs(s - C.r))
            res.append(math.asin(min(1.0, abs(dot(C.d, P.d)))))
            res.append(side)
        else:
            C, L = (F, M) if F.kind == "cylinder" else (M, F)
            res.append(skew_distance(Feat("line", C.p, C.d), L) - C.r)
        return res, None, vk
    raise ValueError(t)


def value_bounds(c, vk):
    """(exact value, lo, hi) of a valued constraint in m / rad (None where not given)."""
    s = math.radians if vk == "angle" else (lambda x: x)
    v = s(c["value"]) if "value" in c else None
    lo = s(c["min"]) if "min" in c else None
    hi = s(c["max"]) if "max" in c else None
    return v, lo, hi


def constraint_report(spec, pose):
    """Per constraint: (worst exact residual, value or None, lo, hi, kind)."""
    fpose = fixed_pose_of(spec)
    out = []
    for c in spec["constraints"]:
        F = world_feature(spec["fixed"]["features"], c["fixed"], fpose)
        M = world_feature(spec["mobile"]["features"], c["mobile"], pose)
        res, val, vk = evaluate(c, F, M)
        worst = max([abs(r) for r in res] + [0.0])
        v, lo, hi = value_bounds(c, vk)
        if val is not None and v is not None:
            worst = max(worst, abs(val - v))
            val = None
        out.append((worst, val, lo, hi, vk))
    return out


def violation(spec, pose):
    """Sum of squared violations (m and rad) at a pose: 0 where every constraint holds."""
    total = 0.0
    for worst, val, lo, hi, _ in constraint_report(spec, pose):
        total += worst * worst
        if val is not None:
            if lo is not None and val < lo:
                total += (lo - val) ** 2
            if hi is not None and val > hi:
                total += (val - hi) ** 2
    return total


def check_feasible(spec, xstar):
    name = spec["name"]
    for c, (worst, val, lo, hi, vk) in zip(spec["constraints"],
                                           constraint_report(spec, xstar)):
        where = f"{name}: constraint '{c['id']}'"
        if worst > EXACT_TOL:
            raise SystemExit(f"{where} violated at X* by {worst:.3g}")
        if val is None:
            continue
        unit_scale = math.radians(1.0) if vk == "angle" else 0.01
        if lo is not None and hi is not None:
            margin = BOUND_MARGIN * (hi - lo)
        else:
            margin = BOUND_MARGIN * max(abs(lo if lo is not None else hi), unit_scale)
        shown = math.degrees(val) if vk == "angle" else val
        if lo is not None and val < lo + margin:
            raise SystemExit(f"{where}: value {shown:.6g} at X* below or within 1% of min")
        if hi is not None and val > hi - margin:
            raise SystemExit(f"{where}: value {shown:.6g} at X* above or within 1% of max")


# A small Nelder-Mead over (position, rotation vector) to double-check infeasibility.


def pose_of_params(x):
    v = x[3:]
    a = norm(v)
    R = axis_angle(v, math.degrees(a)) if a > 1e-12 else rpy(0, 0, 0)
    return Pose(R, x[:3])


def nelder_mead(f, x0, step, iters):
    n = len(x0)
    simplex = [list(x0)] + [[x0[j] + (step[j] if j == i else 0) for j in range(n)]
                            for i in range(n)]
    vals = [f(x) for x in simplex]
    for _ in range(iters):
        order = sorted(range(n + 1), key=lambda i: vals[i])
        simplex, vals = [simplex[i] for i in order], [vals[i] for i in order]
        centroid = [sum(simplex[i][j] for i in range(n)) / n for j in range(n)]
        def towards(t): return [centroid[j] + t * (simplex[-1][j] - centroid[j]) for j in range(n)]
        xr = towards(-1.0)
        fr = f(xr)
        if fr < vals[0]:
            xe = towards(-2.0)
            fe = f(xe)
            simplex[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            simplex[-1], vals[-1] = xr, fr
        else:
            xc = towards(0.5)
            fc = f(xc)
            if fc < vals[-1]:
                simplex[-1], vals[-1] = xc, fc
            else:
                for i in range(1, n + 1):
                    simplex[i] = [simplex[0][j] + 0.5 * (simplex[i][j] - simplex[0][j])
                                  for j in range(n)]
                    vals[i] = f(simplex[i])
    i = min(range(n + 1), key=lambda k: vals[k])
    return simplex[i], vals[i]


def least_violation(spec, starts=24, iters=1500):
    """The least violation found from `starts` random starts around the fixed object."""
    rng = random.Random("relpos-infeasible:" + spec["name"])
    centre = fixed_pose_of(spec).t
    def f(x): return violation(spec, pose_of_params(x))
    best = math.inf
    for _ in range(starts):
        x0 = [centre[i] + rng.uniform(-1, 1) for i in range(3)] + \
             [rng.uniform(-math.pi, math.pi) / math.sqrt(3) for _ in range(3)]
        x, v = nelder_mead(f, x0, [0.1] * 3 + [0.3] * 3, iters)
        x, v = nelder_mead(f, x, [0.01] * 3 + [0.05] * 3, iters)   # restart: polish
        best = min(best, v)
    return best


# ---------------------------------------------------------------------------------------------
# The tasks. Conventions of the mobile objects: a tool's local z is its approach / spray /
# optical axis, pointing from the tool towards the work; its TCP lies on that axis.

Z, X_, Y_ = [0, 0, 1], [1, 0, 0], [0, 1, 0]
DOWN = [0, 0, -1]


def deg_dir(*parts):
    """A unit vector from (weight, vector) pairs: sum of the parts, normalised."""
    v = [0.0, 0.0, 0.0]
    for w, u in parts:
        v = add(v, scale(u, w))
    return unit(v)


def c_(a): return math.cos(math.radians(a))
def s_(a): return math.sin(math.radians(a))


def on_plane(pl, x=None, y=None, z=None):
    """The point of a plane feature (its own frame) with two of its coordinates given."""
    p, n = pl["plane"]["point"], pl["plane"]["normal"]
    q = [x, y, z]
    k = q.index(None)
    rest = sum(n[i] * (q[i] - p[i]) for i in range(3) if i != k)
    q[k] = p[k] - rest / n[k]
    return q


def grasps():
    # Parallel-jaw grasp of a carton from above, jaws across its 120 mm width.
    task("grasp-carton-top-parallel-jaw",
         "Parallel-jaw grasp from above of a 200x120x100 mm carton on the table, jaws across the "
         "120 mm width, fingers 2-5 cm down the sides, within 4 cm of the centre.",
         "carton", {
             "top": plane([0.6, 0.1, 0.1], Z),
             "side_left": plane([0.6, 0.16, 0.05], Y_),
             "mid_across": plane([0.6, 0.1, 0.05], Y_),
             "mid_along": plane([0.6, 0.1, 0.05], X_)},
         "gripper", {
             "tcp": pt(0, 0, 0.16),
             "approach": line([0, 0, 0], Z),
             "jaws": line([0, 0, 0.16], Y_)},
         [con("coincident", "mid_across", "tcp", "TCP centred between the jaws"),
          con("perpendicular", "side_left", "jaws", "jaws close across the 120 mm width",
              orientation="either"),
          con("perpendicular", "top", "approach", "straight down onto the carton",
              orientation="opposed"),
          con("distance", "top", "tcp", "fingers 2-5 cm down the sides", min=-0.05, max=-0.02),
          con("distance", "mid_along", "tcp", "within 4 cm of the centre along the carton",
              min=-0.04, max=0.04)],
         xstar=place(rpy(180, 0, 180), [0, 0, 0.16], [0.61, 0.1, 0.065]))

    # Side grasp of a soda can, jaws horizontal.
    R = frame([c_(20), s_(20), 0], Z)
    task("grasp-soda-can-side",
         "Side grasp of a 66 mm soda can standing on the table: TCP on the can axis 4-8 cm up, "
         "approach and jaws both horizontal.",
         "soda_can", {
             "body": cyl([0.45, -0.12, 0], Z, 0.033),
             "table": plane([0.45, -0.12, 0], Z),
             "lid": plane([0.45, -0.12, 0.115], Z)},
         "gripper", {
             "tcp": pt(0, 0, 0.15),
             "approach": line([0, 0, 0], Z),
             "jaws": line([0, 0, 0.15], Y_)},
         [con("coincident", "body.axis", "tcp", "TCP on the can axis"),
          con("perpendicular", "body.axis", "approach", "approach from the side"),
          con("perpendicular", "body.axis", "jaws", "jaws close across the can"),
          con("distance", "table", "tcp", "grasp 4-8 cm up the can", min=0.04, max=0.08)],
         xstar=place(R, [0, 0, 0.15], [0.45, -0.12, 0.06]))

    # Top-down grasp of a paint can by its rim.
    task("grasp-paint-can-rim-top-down",
         "Top-down grasp of a paint can by its rim: approach down the can axis, fingertips "
         "10-25 mm below the rim; the turn about the axis is free.",
         "paint_can", {
             "axis": line([0.3, 0.25, 0], Z),
             "rim": plane([0.3, 0.25, 0.19], Z)},
         "gripper", {
             "tcp": pt(0, 0, 0.14),
             "approach": line([0, 0, 0], Z)},
         [con("coincident", "axis", "approach", "approach down the can axis",
              orientation="opposed"),
          con("distance", "rim", "tcp", "fingertips 10-25 mm below the rim",
              min=-0.025, max=-0.01)],
         xstar=place(rpy(180, 0, 45), [0, 0, 0.14], [0.3, 0.25, 0.172]))

    # Suction cup on the top of a parcel on a conveyor.
    fp = ([1.2, 0.0, 0.8], [0, 0, 15])
    task("suction-parcel-top-on-conveyor",
         "Single suction cup on the top face of a 300x200x150 mm parcel on a conveyor, at least "
         "5 cm from every edge, tool x within 45 deg of the parcel's long edge.",
         "parcel", {
             "top": plane([0, 0, 0.15], Z),
             "short_side": plane([-0.15, 0, 0.075], X_),
             "long_side": plane([0, -0.1, 0.075], Y_),
             "long_edge": line([-0.15, -0.1, 0.15], X_)},
         "vacuum_tool", {
             "cup_face": plane([0, 0, 0.2], Z),
             "cup_centre": pt(0, 0, 0.2),
             "tool_x": line([0, 0, 0], X_)},
         [con("coincident", "top", "cup_face", "cup flat on the top face", orientation="opposed"),
          con("distance", "short_side", "cup_centre", "5 cm clear of both short edges",
              min=0.05, max=0.25),
          con("distance", "long_side", "cup_centre", "5 cm clear of both long edges",
              min=0.05, max=0.15),
          con("angle", "long_edge", "tool_x", "tool x within 45 deg of the long edge",
              min=0, max=45)],
         xstar=pose_rpy(*fp).then(place(rpy(180, 0, 20), [0, 0, 0.2], [0.02, 0.01, 0.15])),
         fixed_pose=fp)

    # Suction cup on a 30-degree chamfered face of a casting.
    face = plane([0.5, 0, 0.2], [0, -0.5, 0.8660254])
    n = unit(face["plane"]["normal"])
    centre = add([0.5, 0, 0.2], add(scale(X_, 0.006), scale(cross(n, X_), 0.008)))
    task("suction-casting-chamfer-face",
         "Suction cup on the 30-degree chamfered face of a casting, cup centre within 15 mm of "
         "the face's centre.",
         "casting", {
             "chamfer": face,
             "chamfer_centre": pt(0.5, 0, 0.2)},
         "suction_gripper", {
             "cup_face": plane([0, 0, 0.12], Z),
             "cup_centre": pt(0, 0, 0.12)},
         [con("coincident", "chamfer", "cup_face", "cup flat on the chamfer",
              orientation="opposed"),
          con("distance", "chamfer_centre", "cup_centre", "within 15 mm of the face centre",
              max=0.015)],
         xstar=place(frame(scale(n, -1), X_), [0, 0, 0.12], centre))

    # Suction frame on a glass sheet leaning 5 degrees in an A-frame rack.
    sheet = plane([1.0, 0, 0.05], [r7(-c_(5)), 0, r7(s_(5))])
    n = unit(sheet["plane"]["normal"])
    up = unit(sub(Z, scale(n, dot(Z, n))))
    task("suction-glass-sheet-from-rack",
         "Suction frame on a glass sheet leaning 5 deg in an A-frame rack: pads flat on the "
         "glass, frame centre 0.8-1.0 m up and within 5 cm of the sheet's middle, frame upright "
         "within 10 deg.",
         "glass_rack", {
             "sheet": sheet,
             "floor": plane([0, 0, 0], Z),
             "sheet_middle": plane([1.0, 0, 0.5], Y_)},
         "suction_frame", {
             "pad_plane": plane([0, 0, 0.25], Z),
             "frame_centre": pt(0, 0, 0.25),
             "frame_up": line([0, 0, 0.25], X_)},
         [con("coincident", "sheet", "pad_plane", "pads flat on the glass", orientation="opposed"),
          con("distance", "floor", "frame_centre", "frame centre 0.8-1.0 m up", min=0.8, max=1.0),
          con("distance", "sheet_middle", "frame_centre", "centred on the sheet within 5 cm",
              min=-0.05, max=0.05),
          con("angle", "floor", "frame_up", "frame upright within 10 deg", min=80, max=90)],
         xstar=place(frame(scale(n, -1), up), [0, 0, 0.25], on_plane(sheet, y=0.02, z=0.9)))

    # Shaft lying in a V-block, gripped from above.
    task("grasp-shaft-in-vblock-top-down",
         "Top-down parallel-jaw grasp of a shaft lying in a V-block: TCP on the shaft axis, jaws "
         "across it, gripping 40-100 mm in from the free end.",
         "vblock_fixture", {
             "shaft_axis": line([0.5, 0.3, 0.04], X_),
             "shaft_end": plane([0.65, 0.3, 0.04], X_),
             "table": plane([0.5, 0.3, 0], Z)},
         "gripper", {
             "tcp": pt(0, 0, 0.18),
             "approach": line([0, 0, 0], Z),
             "jaws": line([0, 0, 0.18], Y_)},
         [con("coincident", "shaft_axis", "tcp", "TCP on the shaft axis"),
          con("perpendicular", "shaft_axis", "jaws", "jaws across the shaft"),
          con("perpendicular", "table", "approach", "straight down", orientation="opposed"),
          con("distance", "shaft_end", "tcp", "grip 40-100 mm in from the end",
              min=-0.1, max=-0.04)],
         xstar=place(rpy(180, 0, 0), [0, 0, 0.18], [0.58, 0.3, 0.04]))

    # Palm pad pushed against a vertical pipe.
    a = [c_(30), s_(30), 0]
    fingers = deg_dir((c_(10), Z), (s_(10), [-s_(30), c_(30), 0]))
    task("palm-pad-on-vertical-pipe",
         "Palm pad of a gripper pressed against a 100 mm vertical pipe 0.3-0.5 m up, its "
         "fingers within 30 deg of vertical.",
         "pipe", {
             "body": cyl([0.4, -0.2, 0], Z, 0.05),
             "floor": plane([0, 0, 0], Z)},
         "pad_gripper", {
             "palm": plane([0, 0, 0.1], Z),
             "palm_centre": pt(0, 0, 0.1),
             "fingers": line([0, 0, 0.1], X_)},
         [con("tangent", "body", "palm", "palm pad touching the pipe", orientation="opposed"),
          con("distance", "floor", "palm_centre", "contact 0.3-0.5 m up", min=0.3, max=0.5),
          con("angle", "floor", "fingers", "fingers within 30 deg of vertical", min=60, max=90)],
         xstar=place(frame(a, fingers), [0, 0, 0.1],
                     sub([0.4, -0.2, 0.4], scale(a, 0.05))))


def welding():
    # Fillet weld of a tee joint: work and travel angles.
    fp = ([0.8, 0.1, 0.75], [0, 0, 90])
    a = deg_dir((s_(10), X_), (c_(10), deg_dir((c_(45), [0, -1, 0]), (s_(45), DOWN))))
    task("weld-tee-fillet-work-travel-angles",
         "MIG fillet weld of a tee joint on the welding table: wire tip on the root along the "
         "600 mm seam, work angle 45 +- 10 deg to the flange, push angle 5-20 deg.",
         "tee_joint", {
             "seam": line([0, 0, 0], X_),
             "flange": plane([0, 0, 0], Z),
             "web": plane([0, 0, 0], Y_),
             "seam_start": plane([0, 0, 0], X_)},
         "mig_torch", {
             "wire_tip": pt(0, 0, 0.4),
             "torch_axis": line([0, 0, 0], Z)},
         [con("coincident", "seam", "wire_tip", "wire tip on the root of the fillet"),
          con("distance", "seam_start", "wire_tip", "within the 600 mm seam", min=0, max=0.6),
          con("angle", "flange", "torch_axis", "work angle 45 +- 10 deg (axis points down)",
              min=-55, max=-35),
          con("angle", "seam", "torch_axis", "push angle 5-20 deg", min=70, max=85)],
         xstar=pose_rpy(*fp).then(place(frame(a, Z), [0, 0, 0.4], [0.25, 0, 0])),
         fixed_pose=fp)

    # Lap joint: one-sided seam limits.
    fp = ([0.6, -0.3, 0.02], [0, 0, -30])
    a = deg_dir((-s_(5), X_), (c_(5), deg_dir((c_(65), [0, -1, 0]), (s_(65), DOWN))))
    task("weld-lap-joint-seam",
         "MIG lap weld along the edge of a 3 mm plate on a base plate, 20 mm short of each end, "
         "work angle 60-70 deg from the base plate (55-75 allowed), travel angle within 10 deg.",
         "lap_joint", {
             "seam": line([0, 0, 0], X_),
             "base_plate": plane([0, 0, 0], Z),
             "upper_edge": plane([0, 0, 0.0015], Y_),
             "seam_start": plane([0, 0, 0], X_),
             "seam_end": plane([0.4, 0, 0], [-1, 0, 0])},
         "mig_torch", {
             "wire_tip": pt(0, 0, 0.38),
             "torch_axis": line([0, 0, 0], Z)},
         [con("coincident", "seam", "wire_tip", "wire tip on the lap seam"),
          con("distance", "seam_start", "wire_tip", "start 20 mm in", min=0.02),
          con("distance", "seam_end", "wire_tip", "stop 20 mm before the end", min=0.02),
          con("angle", "base_plate", "torch_axis", "work angle 55-75 deg (axis points down)",
              min=-75, max=-55),
          con("angle", "seam", "torch_axis", "travel angle within 10 deg", min=80, max=100)],
         xstar=pose_rpy(*fp).then(place(frame(a, Z), [0, 0, 0.38], [0.15, 0, 0])),
         fixed_pose=fp)

    # Circumferential fillet weld of a pipe on a flange.
    fp = ([1.0, 0.0, 0.8], [0, 0, 0])
    th = 200
    u = [c_(th), s_(th), 0]
    tip = scale(u, 0.0565)
    a = deg_dir((c_(45), scale(u, -1)), (s_(45), DOWN))
    task("weld-pipe-to-flange-circumferential",
         "MIG fillet weld of a DN100 pipe (114.3 mm OD) standing on a flange on the positioner: "
         "tip on the root circle on the robot side, torch aimed at the pipe axis at 45 +- 10 deg "
         "to the flange.",
         "pipe_flange", {
             "pipe_od": cyl([0, 0, 0], Z, 0.05715),
             "flange_face": plane([0, 0, 0], Z),
             "robot_side": plane([0, 0, 0], [-1, 0, 0])},
         "mig_torch", {
             "wire_tip": pt(0, 0, 0.38),
             "torch_axis": line([0, 0, 0], Z)},
         [con("coincident", "pipe_od", "wire_tip", "tip on the pipe wall"),
          con("coincident", "flange_face", "wire_tip", "tip on the flange face"),
          con("angle", "flange_face", "torch_axis", "45 +- 10 deg to the flange (axis down)",
              min=-55, max=-35),
          con("distance", "pipe_od.axis", "torch_axis", "torch aimed at the pipe axis",
              value=0, parallel=False),
          con("distance", "robot_side", "wire_tip", "on the robot's side of the positioner",
              min=0.04)],
         xstar=pose_rpy(*fp).then(place(frame(a, Z), [0, 0, 0.38], scale(u, 0.05715))),
         fixed_pose=fp)
    del tip

    # TIG butt seam: arc length and two tilt limits on one axis.
    fp = ([0.7, 0.2, 0.9], [0, 0, -15])
    a = unit([s_(10), s_(2), -c_(10)])
    task("weld-tig-butt-seam-arc-length",
         "TIG butt weld of two plates: electrode 2-4 mm above the plate and within 0.5 mm of the "
         "joint line along the 500 mm seam, torch within 15 deg of perpendicular, side tilt "
         "within 5 deg.",
         "butt_joint", {
             "plate_top": plane([0, 0, 0], Z),
             "joint_plane": plane([0, 0, 0], Y_),
             "seam_start": plane([0, 0, 0], X_)},
         "tig_torch", {
             "electrode_tip": pt(0, 0, 0.25),
             "torch_axis": line([0, 0, 0], Z)},
         [con("distance", "plate_top", "electrode_tip", "arc length 2-4 mm", min=0.002, max=0.004),
          con("distance", "joint_plane", "electrode_tip", "within 0.5 mm of the joint line",
              min=-0.0005, max=0.0005),
          con("distance", "seam_start", "electrode_tip", "along the 500 mm seam", min=0, max=0.5),
          con("angle", "plate_top", "torch_axis", "within 15 deg of perpendicular (axis down)",
              min=-90, max=-75),
          con("angle", "joint_plane", "torch_axis", "side tilt within 5 deg", min=-5, max=5)],
         xstar=pose_rpy(*fp).then(place(frame(a, X_), [0, 0, 0.25], [0.2, 0.0001, 0.003])),
         fixed_pose=fp)

    # Spot welding gun on a hem flange.
    task("spot-weld-gun-on-door-flange",
         "Spot weld on a vertical door hem flange: the gun's lower electrode square to and "
         "touching the back of the flange within 3 mm of the programmed spot, gun throat "
         "roughly across the flange edge.",
         "door_flange", {
             "flange_back": plane([0.9, 0.4, 1.1], [0, -1, 0]),
             "spot_normal": line([0.9, 0.4, 1.1], [0, 1, 0]),
             "flange_edge": line([0.9, 0.4, 1.115], X_)},
         "spot_gun", {
             "electrode_tip": pt(0, 0, 0),
             "electrode_axis": line([0, 0, 0], Z),
             "throat": line([0, 0, 0], X_)},
         [con("perpendicular", "flange_back", "electrode_axis", "electrode square to the flange",
              orientation="opposed"),
          con("coincident", "flange_back", "electrode_tip", "electrode touching the flange"),
          con("distance", "spot_normal", "electrode_tip", "within 3 mm of the programmed spot",
              max=0.003),
          con("angle", "flange_edge", "throat", "throat across the edge within 30 deg",
              min=60, max=120)],
         xstar=place(frame([0, 1, 0], [s_(15), 0, c_(15)]), [0, 0, 0],
                     [0.901, 0.4, 1.0985]))


def assembly():
    # Dowel pin into a reamed hole.
    task("insert-dowel-pin-depth-range",
         "Insert a dowel pin into a reamed hole of a bushing block: pin coaxial with the hole, "
         "tip 8-20 mm deep; the turn about the axis is free.",
         "bushing_block", {
             "hole_axis": line([0.35, 0, 0.05], Z),
             "top_face": plane([0.35, 0, 0.05], Z)},
         "dowel_pin", {
             "pin_axis": line([0, 0, 0], Z),
             "pin_tip": pt(0, 0, 0)},
         [con("coincident", "hole_axis", "pin_axis", "pin coaxial with the hole"),
          con("distance", "top_face", "pin_tip", "tip 8-20 mm deep", min=-0.02, max=-0.008)],
         xstar=place(rpy(0, 0, 37), [0, 0, 0], [0.35, 0, 0.038]))

    # Shaft with key into a gear hub whose bore is horizontal.
    fp = ([0.55, -0.25, 0.3], [90, 0, 0])
    task("shaft-key-into-gear-hub",
         "Push a keyed shaft into a gear hub clamped with its bore horizontal: shaft in the bore, "
         "shoulder 0.5-2 mm off the hub face, key within 8 deg of the keyway.",
         "gear_hub", {
             "bore": line([0, 0, 0], Z),
             "keyway": line([0, 0, 0], Y_),
             "hub_face": plane([0, 0, 0], Z)},
         "shaft", {
             "axis": line([0, 0, 0], Z),
             "key": line([0, 0, 0.03], Y_),
             "shoulder": plane([0, 0, 0.06], DOWN)},
         [con("coincident", "bore", "axis", "shaft in the bore"),
          con("distance", "hub_face", "shoulder", "shoulder 0.5-2 mm off the hub face",
              orientation="opposed", min=0.0005, max=0.002),
          con("angle", "keyway", "key", "key within 8 deg of the keyway", min=0, max=8)],
         xstar=pose_rpy(*fp).then(Pose(rot_z(3), [0, 0, 0.0012 - 0.06])),
         fixed_pose=fp)

    # M8 bolt through a bracket.
    task("bolt-through-bracket-plate",
         "Drop an M8 bolt through the hole of a bracket plate, head seated on the plate, one "
         "hex flat within 20 deg of the plate edge for the wrench.",
         "bracket", {
             "plate_top": plane([0.4, 0.1, 0.02], Z),
             "hole_axis": line([0.4, 0.1, 0.02], Z),
             "plate_edge": line([0.3, 0.05, 0.02], X_)},
         "m8_bolt", {
             "shank": line([0, 0, 0], Z),
             "head_underside": plane([0, 0, 0], Z),
             "hex_flat": line([0, 0, -0.005], X_)},
         [con("coincident", "hole_axis", "shank", "bolt down through the hole",
              orientation="opposed"),
          con("coincident", "plate_top", "head_underside", "head seated on the plate",
              orientation="opposed"),
          con("angle", "plate_edge", "hex_flat", "a flat within 20 deg of the plate edge",
              min=0, max=20)],
         xstar=place(rpy(180, 0, -12), [0, 0, 0], [0.4, 0.1, 0.02]))

    # Part on a fixture with a round and a diamond locating pin.
    fp = ([1.1, -0.4, 0.85], [0, 0, 30])
    task("part-on-fixture-two-locating-pins",
         "Load a bracket onto a welding fixture: flat on the base, its round hole on the round "
         "pin and its slot on the diamond pin (300 mm apart).",
         "welding_fixture", {
             "base": plane([0, 0, 0], Z),
             "round_pin": line([0.1, 0.05, 0], Z),
             "diamond_pin": line([0.4, 0.05, 0], Z)},
         "bracket_part", {
             "bottom": plane([0, 0, 0], DOWN),
             "round_hole": pt(0.02, 0.03, 0),
             "slot_centre": pt(0.32, 0.03, 0)},
         [con("coincident", "base", "bottom", "part flat on the fixture base",
              orientation="opposed"),
          con("coincident", "round_pin", "round_hole", "round hole on the round pin"),
          con("coincident", "diamond_pin", "slot_centre", "slot on the diamond pin")],
         xstar=pose_rpy(*fp).then(Pose(rpy(0, 0, 0), [0.08, 0.02, 0])),
         fixed_pose=fp)

    # Carton pushed into the corner of a pallet against two fences, with a gap.
    task("carton-into-pallet-corner-gap",
         "Place a carton on the pallet deck into the corner formed by two fences, 2-10 mm off "
         "each fence.",
         "pallet_corner", {
             "deck": plane([0, 0, 0.144], Z),
             "back_fence": plane([0, 0, 0], X_),
             "side_fence": plane([0, 0, 0], Y_)},
         "carton", {
             "bottom": plane([0, 0, 0], DOWN),
             "back_face": plane([0, 0.1, 0.15], [-1, 0, 0]),
             "side_face": plane([0.1, 0, 0.15], [0, -1, 0])},
         [con("coincident", "deck", "bottom", "carton flat on the deck", orientation="opposed"),
          con("distance", "back_fence", "back_face", "2-10 mm off the back fence",
              orientation="opposed", min=0.002, max=0.01),
          con("distance", "side_fence", "side_face", "2-10 mm off the side fence",
              orientation="opposed", min=0.002, max=0.01)],
         xstar=Pose(rpy(0, 0, 0), [0.005, 0.006, 0.144]))

    # Tilted peg insertion.
    a = unit([s_(5) * c_(30), s_(5) * s_(30), -c_(5)])
    task("peg-tilted-insertion-start",
         "Start of a tilted peg-in-hole insertion: peg tip on the hole axis just inside the "
         "chamfer (0-3 mm), peg tilted 3-8 deg from the hole axis.",
         "housing", {
             "hole_axis": line([0.5, 0.2, 0.1], DOWN),
             "hole_top": plane([0.5, 0.2, 0.1], Z)},
         "peg", {
             "peg_axis": line([0, 0, 0], Z),
             "peg_tip": pt(0, 0, 0.06)},
         [con("coincident", "hole_axis", "peg_tip", "peg tip on the hole axis"),
          con("distance", "hole_top", "peg_tip", "tip 0-3 mm inside the chamfer",
              min=-0.003, max=0),
          con("angle", "hole_axis", "peg_axis", "peg tilted 3-8 deg for the tilt insertion",
              min=3, max=8)],
         xstar=place(frame(a, X_), [0, 0, 0.06], [0.5, 0.2, 0.0985]))

    # Bearing pressed into a horizontal bore.
    fp = ([0.6, 0.3, 0.4], [0, 90, 0])
    task("bearing-press-into-housing-bore",
         "Press a 6204 bearing (14 mm wide) into a gearbox housing bore: coaxial, front face "
         "within 0.5 mm of the bore shoulder, back face 10-20 mm below the housing face.",
         "gearbox_housing", {
             "bore": line([0, 0, 0], Z),
             "housing_face": plane([0, 0, 0], Z),
             "bore_shoulder": plane([0, 0, -0.03], Z)},
         "bearing_6204", {
             "axis": line([0, 0, 0], Z),
             "front_face": plane([0, 0, 0], DOWN),
             "back_face": plane([0, 0, 0.014], Z)},
         [con("coincident", "bore", "axis", "bearing coaxial with the bore"),
          con("distance", "bore_shoulder", "front_face", "seated within 0.5 mm of the shoulder",
              orientation="opposed", min=0, max=0.0005),
          con("distance", "housing_face", "back_face", "back face 10-20 mm below the face",
              min=-0.02, max=-0.01)],
         xstar=pose_rpy(*fp).then(Pose(rot_z(25), [0, 0, -0.03 + 0.0002])),
         fixed_pose=fp)

    # Pulley on a motor shaft, set screw onto the D-flat.
    fp = ([0.3, 0.5, 0.25], [0, 0, 0])
    task("pulley-on-motor-shaft-setscrew",
         "Slide a timing pulley onto a motor shaft: coaxial, hub 3-6 mm clear of the motor "
         "face, set screw within 10 deg of square onto the shaft's D-flat.",
         "motor_shaft", {
             "shaft_axis": line([0, 0, 0], X_),
             "d_flat": plane([0, 0, 0.006], Z),
             "motor_face": plane([0, 0, 0], X_)},
         "timing_pulley", {
             "bore": line([0, 0, 0], X_),
             "hub_back": plane([0, 0, 0], [-1, 0, 0]),
             "setscrew": line([0.008, 0, 0], DOWN)},
         [con("coincident", "shaft_axis", "bore", "pulley on the shaft"),
          con("distance", "motor_face", "hub_back", "hub 3-6 mm clear of the motor face",
              orientation="opposed", min=0.003, max=0.006),
          con("angle", "d_flat", "setscrew", "set screw within 10 deg of square to the flat",
              min=-90, max=-80)],
         xstar=pose_rpy(*fp).then(Pose(rot_x(-4), [0.0045, 0, 0])),
         fixed_pose=fp)

    # Cabinet door hung on its hinge pin and opened for the next station.
    task("hang-door-on-hinge-open",
         "Hang a cabinet door on its hinge pin, knuckle resting on the lower hinge, and hold it "
         "open 80-100 deg for the next station.",
         "cabinet", {
             "hinge_pin": line([0, 0, 0], Z),
             "front": plane([0, 0, 0], [0, -1, 0]),
             "hinge_seat": plane([0, 0, 0.1], Z)},
         "door", {
             "hinge_axis": line([0, 0, 0], Z),
             "outer_face": plane([0, 0, 0], [0, -1, 0]),
             "knuckle_bottom": plane([0, 0, 0.1], DOWN)},
         [con("coincident", "hinge_pin", "hinge_axis", "door on the hinge pin"),
          con("coincident", "hinge_seat", "knuckle_bottom", "knuckle resting on the lower hinge",
              orientation="opposed"),
          con("angle", "front", "outer_face", "door open 80-100 deg", min=80, max=100)],
         xstar=Pose(rot_z(87), [0, 0, 0]))


def painting_dispensing():
    # Spray gun in front of a vertical panel.
    a = unit([c_(3) * c_(8), c_(3) * s_(8), -s_(3)])
    task("spray-vertical-panel-standoff",
         "Spray a 1.2x0.8 m vertical panel on a paint stand: gun 150-250 mm off the panel, "
         "within 15 deg of square, level within 10 deg, nozzle over the panel.",
         "paint_stand", {
             "panel": plane([1.5, 0, 1.0], [-1, 0, 0]),
             "panel_left": plane([1.5, -0.6, 1.0], Y_),
             "panel_bottom": plane([1.5, 0, 0.5], Z),
             "floor": plane([0, 0, 0], Z)},
         "spray_gun", {
             "nozzle": pt(0, 0, 0.22),
             "spray_axis": line([0, 0, 0.22], Z)},
         [con("distance", "panel", "nozzle", "gun 150-250 mm off the panel", min=0.15, max=0.25),
          con("angle", "panel", "spray_axis", "spray within 15 deg of square", min=-90, max=-75),
          con("distance", "panel_left", "nozzle", "over the 1.2 m width", min=0, max=1.2),
          con("distance", "panel_bottom", "nozzle", "over the 0.8 m height", min=0, max=0.8),
          con("angle", "floor", "spray_axis", "gun level within 10 deg", min=-10, max=10)],
         xstar=place(frame(a, Z), [0, 0, 0.22], [1.3, 0.1, 0.9]))

    # Glue bead along a sheet-metal flange.
    a = unit([-s_(10), 0, -c_(10)])
    task("glue-bead-along-flange",
         "Dispense a glue bead along a 350 mm sheet-metal flange: tip 2-4 mm above it and within "
         "0.5 mm of the bead path, nozzle within 20 deg of vertical and trailing 0-20 deg.",
         "sheet_metal_flange", {
             "flange_top": plane([0.5, -0.2, 0.3], Z),
             "bead_plane": plane([0.5, -0.2, 0.3], Y_),
             "bead_path": line([0.5, -0.2, 0.3], X_),
             "bead_start": plane([0.5, -0.2, 0.3], X_)},
         "glue_nozzle", {
             "tip": pt(0, 0, 0.12),
             "nozzle_axis": line([0, 0, 0], Z)},
         [con("distance", "flange_top", "tip", "tip 2-4 mm above the flange",
              min=0.002, max=0.004),
          con("distance", "bead_plane", "tip", "on the bead path within 0.5 mm",
              min=-0.0005, max=0.0005),
          con("distance", "bead_start", "tip", "along the 350 mm bead", min=0, max=0.35),
          con("angle", "flange_top", "nozzle_axis", "within 20 deg of vertical (axis down)",
              min=-90, max=-70),
          con("angle", "bead_path", "nozzle_axis", "trailing the bead 0-20 deg",
              min=90, max=110)],
         xstar=place(frame(a, X_), [0, 0, 0.12], [0.62, -0.1998, 0.303]))

    # Sealant ring around a horizontal pipe at a sleeve joint.
    u = [s_(-40), 0, c_(-40)]
    t = [c_(-40), 0, -s_(-40)]
    beta = math.degrees(math.asin(0.001 / 0.0345))
    a = deg_dir((c_(beta), scale(u, -1)), (s_(beta), t))
    task("sealant-ring-around-pipe-joint",
         "Seal a sleeve joint on a horizontal 60 mm pipe: nozzle tip 3-6 mm off the pipe on the "
         "joint line, nozzle square to the pipe and aimed within 2 mm of its centre.",
         "pipe_joint", {
             "pipe": cyl([0.6, 0, 0.4], Y_, 0.03),
             "joint_plane": plane([0.6, 0.1, 0.4], Y_)},
         "sealant_nozzle", {
             "tip": pt(0, 0, 0.1),
             "nozzle_axis": line([0, 0, 0], Z)},
         [con("distance", "pipe.axis", "tip", "tip 3-6 mm off the pipe surface",
              min=0.033, max=0.036),
          con("coincident", "joint_plane", "tip", "tip on the joint line"),
          con("perpendicular", "pipe.axis", "nozzle_axis", "nozzle square to the pipe"),
          con("distance", "pipe.axis", "nozzle_axis", "aimed within 2 mm of the pipe centre",
              parallel=False, max=0.002)],
         xstar=place(frame(a, Y_), [0, 0, 0.1], add([0.6, 0.1, 0.4], scale(u, 0.0345))))

    # Spray the shell of a vertical tank.
    u = [c_(190), s_(190), 0]
    task("spray-tank-shell-standoff",
         "Spray the shell of a 1 m diameter vertical tank: nozzle 200-300 mm off the shell, "
         "spray horizontal and aimed at the tank axis, nozzle 0.3-1.8 m up.",
         "storage_tank", {
             "shell": cyl([2.0, 0, 0], Z, 0.5),
             "floor": plane([0, 0, 0], Z)},
         "spray_gun", {
             "nozzle": pt(0, 0, 0.22),
             "spray_axis": line([0, 0, 0.22], Z)},
         [con("distance", "shell.axis", "nozzle", "nozzle 200-300 mm off the shell",
              min=0.7, max=0.8),
          con("distance", "shell.axis", "spray_axis", "spray aimed at the tank axis",
              value=0, parallel=False),
          con("perpendicular", "shell.axis", "spray_axis", "spray horizontal"),
          con("distance", "floor", "nozzle", "within the band being painted", min=0.3, max=1.8)],
         xstar=place(frame(scale(u, -1), Z), [0, 0, 0.22], add([2.0, 0, 1.1], scale(u, 0.75))))

    # Conformal-coating nozzle over a circuit board, two tilt ranges.
    fp = ([0.4, 0.4, 0.12], [0, 0, 45])
    a = unit([s_(12), -s_(5), -1])
    task("conformal-coat-board-edge",
         "Conformal coating along a circuit board's connector edge: nozzle 8-15 mm above the "
         "board, 5-15 mm in from the edge, tilted 5-20 deg away from the connector and within "
         "10 deg sideways.",
         "circuit_board", {
             "board_top": plane([0, 0, 0], Z),
             "connector_edge": plane([0, 0, 0], [-1, 0, 0]),
             "edge_plane_across": plane([0, 0, 0], Y_)},
         "coating_valve", {
             "nozzle_tip": pt(0, 0, 0.09),
             "nozzle_axis": line([0, 0, 0], Z)},
         [con("distance", "board_top", "nozzle_tip", "8-15 mm above the board",
              min=0.008, max=0.015),
          con("distance", "connector_edge", "nozzle_tip", "5-15 mm in from the connector edge",
              min=-0.015, max=-0.005),
          con("distance", "edge_plane_across", "nozzle_tip", "along the 80 mm edge",
              min=0, max=0.08),
          con("angle", "connector_edge", "nozzle_axis", "tilted 5-20 deg away from the connector",
              min=-20, max=-5),
          con("angle", "edge_plane_across", "nozzle_axis", "within 10 deg sideways",
              min=-10, max=10)],
         xstar=pose_rpy(*fp).then(place(frame(a, X_), [0, 0, 0.09], [0.01, 0.04, 0.012])),
         fixed_pose=fp)


def inspection():
    # Camera looking at a weld bead.
    a = unit([s_(10) * c_(20), s_(10) * s_(20), -c_(10)])
    target = [0.7, 0.1, 0.35]
    task("camera-inspect-weld-bead",
         "Inspect a weld bead with a camera: bead point on the optical axis at a 250-350 mm "
         "working distance, view within 15 deg of the surface normal.",
         "weldment", {
             "bead_point": pt(*target),
             "surface": plane(target, Z)},
         "inspection_camera", {
             "lens_centre": pt(0, 0, 0.08),
             "optical_axis": line([0, 0, 0.08], Z)},
         [con("distance", "bead_point", "lens_centre", "working distance 250-350 mm",
              min=0.25, max=0.35),
          con("coincident", "bead_point", "optical_axis", "bead on the optical axis"),
          con("angle", "surface", "optical_axis", "within 15 deg of the normal (looking down)",
              min=-90, max=-75)],
         xstar=place(frame(a, X_), [0, 0, 0.08], sub(target, scale(a, 0.3))))

    # Barcode camera reading a label on a rack, image rows level.
    a = [c_(25), -s_(25), 0]
    label = [2.0, 0.5, 1.2]
    task("camera-read-rack-label-level",
         "Read a barcode label on a rack upright: label on the optical axis 0.4-0.8 m away, "
         "within 30 deg of facing the rack, image rows level.",
         "rack", {
             "label": pt(*label),
             "rack_face": plane([2.0, 0, 0], [-1, 0, 0]),
             "floor": plane([0, 0, 0], Z)},
         "barcode_camera", {
             "optic_centre": pt(0, 0, 0),
             "optical": line([0, 0, 0], Z),
             "image_rows": line([0, 0, 0], X_)},
         [con("coincident", "label", "optical", "label on the optical axis"),
          con("distance", "label", "optic_centre", "reading distance 0.4-0.8 m",
              min=0.4, max=0.8),
          con("angle", "rack_face", "optical", "within 30 deg of facing the rack",
              min=-90, max=-60),
          con("parallel", "floor", "image_rows", "image rows level")],
         xstar=place(frame(a, [s_(25), c_(25), 0]), [0, 0, 0], sub(label, scale(a, 0.6))))

    # Laser line profiler over a seam.
    a = [0, s_(4), -c_(4)]
    task("laser-profiler-over-seam",
         "Laser line profiler tracking a seam: laser line across the seam, sensor 90-130 mm "
         "above the part and within 10 mm of the seam sideways, within 10 deg of looking "
         "straight down.",
         "seam_part", {
             "seam": line([0.4, -0.1, 0.2], X_),
             "surface": plane([0.4, -0.1, 0.2], Z),
             "seam_plane": plane([0.4, -0.1, 0.2], Y_)},
         "laser_profiler", {
             "sensor_origin": pt(0, 0, 0),
             "laser_plane": plane([0, 0, 0], X_),
             "optical": line([0, 0, 0], Z)},
         [con("perpendicular", "seam", "laser_plane", "laser line across the seam",
              orientation="either"),
          con("distance", "surface", "sensor_origin", "within the 90-130 mm measuring range",
              min=0.09, max=0.13),
          con("distance", "seam_plane", "sensor_origin", "within 10 mm of the seam sideways",
              min=-0.01, max=0.01),
          con("angle", "surface", "optical", "within 10 deg of looking straight down",
              min=-90, max=-80)],
         xstar=place(frame(a, X_), [0, 0, 0], [0.5, -0.097, 0.31]))

    # Overview camera above a parts tray.
    fp = ([0.5, -0.3, 0.75], [0, 0, 10])
    a = unit([s_(8) * c_(30), s_(8) * s_(30), -c_(8)])
    task("camera-overview-parts-tray",
         "Overview camera over a parts tray: tray centre on the optical axis 0.5-0.7 m away, "
         "within 20 deg of looking straight down, image rows within 10 deg of the tray's long "
         "edge.",
         "parts_tray", {
             "tray_centre": pt(0, 0, 0.02),
             "tray_floor": plane([0, 0, 0.02], Z),
             "long_edge": line([-0.2, -0.15, 0.02], X_)},
         "overview_camera", {
             "centre": pt(0, 0, 0),
             "optical": line([0, 0, 0], Z),
             "image_rows": line([0, 0, 0], X_)},
         [con("coincident", "tray_centre", "optical", "tray centre on the optical axis"),
          con("distance", "tray_centre", "centre", "0.5-0.7 m to fit the tray in view",
              min=0.5, max=0.7),
          con("angle", "tray_floor", "optical", "within 20 deg of looking straight down",
              min=-90, max=-70),
          con("angle", "long_edge", "image_rows", "image rows along the tray within 10 deg",
              min=0, max=10)],
         xstar=pose_rpy(*fp).then(place(frame(a, X_), [0, 0, 0],
                                        sub([0, 0, 0.02], scale(a, 0.6)))),
         fixed_pose=fp)

    # Borescope into a bore, view window towards an oil port.
    task("borescope-into-cylinder-bore",
         "Borescope inspection of an engine cylinder bore: probe coaxial with the bore, its "
         "side-view window 40-90 mm down and turned within 30 deg of the oil port.",
         "engine_block", {
             "bore_axis": line([0.6, 0.0, 0.3], DOWN),
             "deck": plane([0.6, 0.0, 0.3], Z),
             "oil_port_dir": line([0.6, 0.0, 0.25], Y_)},
         "borescope", {
             "probe_axis": line([0, 0, 0], Z),
             "window": pt(0, 0, 0.35),
             "view_dir": line([0, 0, 0.35], X_)},
         [con("coincident", "bore_axis", "probe_axis", "probe coaxial with the bore"),
          con("distance", "deck", "window", "window 40-90 mm below the deck",
              min=-0.09, max=-0.04),
          con("angle", "oil_port_dir", "view_dir", "looking within 30 deg of the oil port",
              min=0, max=30)],
         xstar=place(frame(DOWN, [-s_(12), c_(12), 0]), [0, 0, 0.35], [0.6, 0.0, 0.24]))


def deburr_screw_pallet():
    # Deburring a block's top edge at 45 degrees.
    fp = ([0.5, 0.0, 0.8], [0, 0, 45])
    a = unit([s_(5), -c_(5) / math.sqrt(2), -c_(5) / math.sqrt(2)])
    task("deburr-block-top-edge-45",
         "Deburr the 300 mm top front edge of a machined block: cutter tip on the edge 10 mm "
         "from each end, spindle 45 +- 10 deg to both faces and within 10 deg of square to the "
         "edge.",
         "machined_block", {
             "edge": line([0, 0, 0], X_),
             "top": plane([0, 0, 0], Z),
             "front": plane([0, 0, 0], Y_),
             "edge_start": plane([0, 0, 0], X_)},
         "deburring_spindle", {
             "cutter_tip": pt(0, 0, 0.2),
             "spindle": line([0, 0, 0], Z)},
         [con("coincident", "edge", "cutter_tip", "cutter tip on the edge"),
          con("distance", "edge_start", "cutter_tip", "10 mm clear of each end",
              min=0.01, max=0.29),
          con("angle", "top", "spindle", "45 +- 10 deg to the top face", min=-55, max=-35),
          con("angle", "front", "spindle", "45 +- 10 deg to the front face", min=-55, max=-35),
          con("angle", "edge", "spindle", "within 10 deg of square to the edge",
              min=80, max=100)],
         xstar=pose_rpy(*fp).then(place(frame(a, Z), [0, 0, 0.2], [0.12, 0, 0])),
         fixed_pose=fp)

    # Countersink a drilled hole.
    task("countersink-drilled-hole",
         "Countersink/deburr a drilled hole in a plate: tool on the hole axis pointing down, "
         "tip 1-2 mm below the surface.",
         "plate", {
             "hole_axis": line([0.3, 0.3, 0.01], Z),
             "plate_top": plane([0.3, 0.3, 0.01], Z)},
         "countersink_tool", {
             "tool_axis": line([0, 0, 0], Z),
             "tip": pt(0, 0, 0.15)},
         [con("coincident", "hole_axis", "tool_axis", "tool on the hole axis, pointing down",
              orientation="opposed"),
          con("distance", "plate_top", "tip", "tip 1-2 mm below the surface",
              min=-0.002, max=-0.001)],
         xstar=place(rpy(180, 0, 60), [0, 0, 0.15], [0.3, 0.3, 0.0085]))

    # Screwdriving an M5 into a boss.
    fp = ([0.45, 0.35, 0.05], [0, 0, -20])
    task("screwdrive-m5-into-boss",
         "Drive an M5 screw into a boss of an electronics housing: bit on the screw axis "
         "pointing down, bit tip 1-4 mm above the boss (in the screw head's recess).",
         "electronics_housing", {
             "screw_hole": line([0.08, 0.04, 0.03], Z),
             "boss_top": plane([0.08, 0.04, 0.03], Z)},
         "screwdriver", {
             "bit_axis": line([0, 0, 0], Z),
             "bit_tip": pt(0, 0, 0.21)},
         [con("coincident", "screw_hole", "bit_axis", "bit on the screw axis",
              orientation="opposed"),
          con("distance", "boss_top", "bit_tip", "bit tip in the screw head recess",
              min=0.001, max=0.004)],
         xstar=pose_rpy(*fp).then(place(rpy(180, 0, 10), [0, 0, 0.21], [0.08, 0.04, 0.0325])),
         fixed_pose=fp)

    # Screwdriving into a hole on an inclined face, with tilt and position tolerances.
    face = plane([0.6, -0.1, 0.2], [0, r7(-s_(20)), r7(c_(20))])
    n = unit(face["plane"]["normal"])
    bit = unit(mat_vec(axis_angle(X_, 1.0), scale(n, -1)))
    inplane = unit(cross(n, X_))
    task("screwdrive-inclined-face-tilt-tolerance",
         "Drive a screw into a hole on a 20-deg inclined face: bit within 2 deg of the hole "
         "axis, bit tip within 0.5 mm of it and 3-6 mm above the face.",
         "inclined_bracket", {
             "face": face,
             "screw_axis": line([0.6, -0.1, 0.2], face["plane"]["normal"])},
         "screwdriver", {
             "bit_axis": line([0, 0, 0], Z),
             "bit_tip": pt(0, 0, 0.21)},
         [con("angle", "screw_axis", "bit_axis", "bit within 2 deg of the hole axis (pointing in)",
              min=178, max=180),
          con("distance", "screw_axis", "bit_tip", "bit tip within 0.5 mm of the hole axis",
              max=0.0005),
          con("distance", "face", "bit_tip", "bit tip 3-6 mm above the face (screw head)",
              min=0.003, max=0.006)],
         xstar=place(frame(bit, X_), [0, 0, 0.21],
                     add([0.6, -0.1, 0.2], add(scale(n, 0.0045), scale(inplane, 0.0002)))))

    # Palletizing a carton on the second layer.
    fp = ([1.5, -0.8, 0.0], [0, 0, 90])
    task("palletize-carton-second-layer",
         "Place a 400x300x250 mm carton on the second layer of a Euro pallet: flat on layer 1, "
         "its centre at 0.8 m / 0.2 m from the pallet edges +- 5 mm, long side along the "
         "pallet's short side within 2 deg.",
         "euro_pallet", {
             "layer1_top": plane([0, 0, 0.394], Z),
             "front_edge": plane([0, 0, 0], X_),
             "left_edge": plane([0, 0, 0], Y_),
             "short_side": line([0, 0, 0.144], Y_)},
         "carton", {
             "bottom": plane([0, 0, 0], DOWN),
             "bottom_centre": pt(0, 0, 0),
             "long_side": line([0, 0, 0], X_)},
         [con("coincident", "layer1_top", "bottom", "flat on layer 1", orientation="opposed"),
          con("distance", "front_edge", "bottom_centre", "0.8 m from the front edge +- 5 mm",
              min=0.795, max=0.805),
          con("distance", "left_edge", "bottom_centre", "0.2 m from the left edge +- 5 mm",
              min=0.195, max=0.205),
          con("angle", "short_side", "long_side", "long side along the short side within 2 deg",
              min=0, max=2)],
         xstar=pose_rpy(*fp).then(Pose(rot_z(91), [0.801, 0.198, 0.394])),
         fixed_pose=fp)

    # Depalletizing with a vacuum gripper from the top layer.
    fp = ([1.4, 0.6, 0.0], [0, 0, -90])
    task("depalletize-vacuum-top-layer",
         "Pick a carton from the top layer with a vacuum gripper: pads flat on its top, within "
         "30 mm of its centre, tool x within 30 deg of the pallet edge to keep the hose clear.",
         "pallet_stack", {
             "carton_top": plane([0.3, 0.2, 1.144], Z),
             "carton_centre": pt(0.3, 0.2, 1.144),
             "pallet_edge": line([0, 0, 0.144], X_)},
         "vacuum_gripper", {
             "pad_face": plane([0, 0, 0.18], Z),
             "pad_centre": pt(0, 0, 0.18),
             "tool_x": line([0, 0, 0], X_)},
         [con("coincident", "carton_top", "pad_face", "pads flat on the carton top",
              orientation="opposed"),
          con("distance", "carton_centre", "pad_centre", "within 30 mm of the carton centre",
              max=0.03),
          con("angle", "pallet_edge", "tool_x", "tool x within 30 deg of the pallet edge",
              min=0, max=30)],
         xstar=pose_rpy(*fp).then(place(rpy(180, 0, -12), [0, 0, 0.18], [0.31, 0.19, 1.144])),
         fixed_pose=fp)

    # Machine tending: place a blank in a vise against the fixed jaw and the stop.
    fp = ([0.9, -0.5, 0.95], [0, 0, 0])
    task("machine-tending-blank-in-vise",
         "Load a 100x60x40 mm blank into a machine vise: on the parallels, against the fixed "
         "jaw, 0-1 mm off the end stop, top 8-12 mm above the jaws for clamping clearance.",
         "machine_vise", {
             "parallels": plane([0, 0, 0], Z),
             "fixed_jaw": plane([0, 0, 0], Y_),
             "end_stop": plane([0, 0, 0], X_),
             "jaw_top": plane([0, 0, 0.03], Z)},
         "blank", {
             "bottom": plane([0, 0, 0], DOWN),
             "side": plane([0, 0, 0.02], [0, -1, 0]),
             "end": plane([0, 0.03, 0.02], [-1, 0, 0]),
             "top": plane([0, 0, 0.04], Z)},
         [con("coincident", "parallels", "bottom", "blank on the parallels",
              orientation="opposed"),
          con("coincident", "fixed_jaw", "side", "against the fixed jaw", orientation="opposed"),
          con("distance", "end_stop", "end", "0-1 mm off the end stop", orientation="opposed",
              min=0, max=0.001),
          con("distance", "jaw_top", "top", "top 8-12 mm above the jaws",
              min=0.008, max=0.012)],
         xstar=pose_rpy(*fp).then(Pose(rpy(0, 0, 0), [0.0004, 0, 0])),
         fixed_pose=fp)


def infeasible():
    # 1. Reach: the wrist centre cannot both be within reach and 150 mm behind a far TCP.
    task("infeasible-pick-beyond-reach",
         "Infeasible: the pick point is 1.086 m from the shoulder and the wrist centre lies "
         "0.15 m behind the TCP, so the wrist is at least 0.936 m from the shoulder, beyond "
         "its 0.85 m reach.",
         "robot_cell", {
             "shoulder": pt(0, 0, 0.4),
             "pick_point": pt(0.9, 0.6, 0.3)},
         "gripper", {
             "wrist_centre": pt(0, 0, 0),
             "tcp": pt(0, 0, 0.15)},
         [con("distance", "shoulder", "wrist_centre", "wrist centre within the 0.85 m reach",
              max=0.85),
          con("coincident", "pick_point", "tcp", "TCP on the pick point")],
         near=place(frame(DOWN, X_), [0, 0, 0.15], [0.9, 0.6, 0.3]))

    # 2. Two view-angle ranges on the optical axis that cannot both hold.
    task("infeasible-camera-two-view-angles",
         "Infeasible: the optical axis must be within 10 deg of facing the vertical wall and "
         "within 20 deg of looking straight down; the wall normal and the vertical are 90 deg "
         "apart, more than 10 + 20 deg.",
         "cell", {
             "wall": plane([2.0, 0, 0], [-1, 0, 0]),
             "floor": plane([0, 0, 0], Z),
             "target": pt(2.0, 0, 1.0)},
         "camera", {
             "centre": pt(0, 0, 0),
             "optical": line([0, 0, 0], Z)},
         [con("angle", "wall", "optical", "within 10 deg of facing the wall", min=-90, max=-80),
          con("angle", "floor", "optical", "within 20 deg of looking straight down",
              min=-90, max=-70),
          con("coincident", "target", "optical", "target on the optical axis")],
         near=place(frame(X_, Z), [0, 0, 0], [1.5, 0, 1.0]))

    # 3. A hard stop that contradicts the nozzle standoff.
    task("infeasible-dispense-standoff-vs-hard-stop",
         "Infeasible: the head's stop face rests on the stop 50 mm above the part, and the "
         "nozzle tip sits 60 mm beyond the stop face, so the tip is 10 mm below the part "
         "surface, not 5-10 mm above it.",
         "dispense_fixture", {
             "stop": plane([0.5, 0, 0.05], Z),
             "part_surface": plane([0.5, 0, 0], Z)},
         "dispensing_head", {
             "stop_face": plane([0, 0, 0], Z),
             "nozzle_tip": pt(0, 0, 0.06)},
         [con("coincident", "stop", "stop_face", "head down on the hard stop",
              orientation="opposed"),
          con("distance", "part_surface", "nozzle_tip", "nozzle 5-10 mm above the part",
              min=0.005, max=0.01)],
         near=place(frame(DOWN, X_), [0, 0, 0], [0.5, 0, 0.05]))

    # 4. A suction cup on a vertical face with a top-down approach range.
    task("infeasible-suction-side-face-top-approach",
         "Infeasible: a cup flat on the carton's vertical side face has a horizontal axis "
         "(0 deg to the floor), but the approach must be within 30 deg of straight down.",
         "carton", {
             "side_face": plane([0.5, 0.1, 0.1], Y_),
             "floor": plane([0, 0, 0], Z)},
         "suction_tool", {
             "cup_face": plane([0, 0, 0.15], Z),
             "approach": line([0, 0, 0], Z)},
         [con("coincident", "side_face", "cup_face", "cup flat on the side face",
              orientation="opposed"),
          con("angle", "floor", "approach", "approach within 30 deg of straight down",
              min=-90, max=-60)],
         near=place(frame([0, -1, 0], Z), [0, 0, 0.15], [0.5, 0.1, 0.1]))

    # 5. A pin too short for the insertion depth.
    task("infeasible-pin-too-short-for-depth",
         "Infeasible: with the pin's shoulder seated on the top face the tip is 20 mm (the "
         "shoulder-to-tip length) below it, not 30-40 mm.",
         "bushing_block", {
             "hole_axis": line([0.35, 0, 0.05], Z),
             "top_face": plane([0.35, 0, 0.05], Z)},
         "shoulder_pin", {
             "pin_axis": line([0, 0, 0], Z),
             "pin_tip": pt(0, 0, 0),
             "shoulder": plane([0, 0, 0.02], DOWN)},
         [con("coincident", "hole_axis", "pin_axis", "pin coaxial with the hole"),
          con("coincident", "top_face", "shoulder", "shoulder seated on the top face",
              orientation="opposed"),
          con("distance", "top_face", "pin_tip", "tip 30-40 mm deep", min=-0.04, max=-0.03)],
         near=Pose(rpy(0, 0, 0), [0.35, 0, 0.03]))

    # 6. A camera standoff inside a safety plane it must stay behind.
    task("infeasible-camera-behind-safety-plane",
         "Infeasible: the camera must be 0.3-0.5 m from the target yet at least 0.6 m behind "
         "the fixture plane through the target; a point's distance to a plane through the "
         "target never exceeds its distance to the target.",
         "fixture", {
             "target": pt(0.8, 0, 0.5),
             "fixture_face": plane([0.8, 0, 0.5], [-1, 0, 0])},
         "camera", {
             "centre": pt(0, 0, 0),
             "optical": line([0, 0, 0], Z)},
         [con("distance", "target", "centre", "working distance 0.3-0.5 m", min=0.3, max=0.5),
          con("distance", "fixture_face", "centre", "at least 0.6 m behind the fixture face",
              min=0.6),
          con("coincident", "target", "optical", "target on the optical axis")],
         near=place(frame(X_, Z), [0, 0, 0], [0.4, 0, 0.5]))

    # 7. A near-vertical torch cannot also be 30-60 deg from a vertical wall.
    task("infeasible-torch-vertical-vs-wall-angle",
         "Infeasible: a torch within 10 deg of vertical makes at most 10 deg with the vertical "
         "wall plate, so it cannot be 30-60 deg from it.",
         "corner_joint", {
             "seam": line([0.6, 0, 0], Y_),
             "floor_plate": plane([0.6, 0, 0], Z),
             "wall_plate": plane([0.6, 0, 0], [-1, 0, 0])},
         "mig_torch", {
             "wire_tip": pt(0, 0, 0.4),
             "torch_axis": line([0, 0, 0], Z)},
         [con("coincident", "seam", "wire_tip", "wire tip on the seam"),
          con("angle", "floor_plate", "torch_axis", "within 10 deg of vertical (axis down)",
              min=-90, max=-80),
          con("angle", "wall_plate", "torch_axis", "30-60 deg to the wall plate",
              min=30, max=60)],
         near=place(frame(DOWN, X_), [0, 0, 0.4], [0.6, 0.1, 0]))

    # 8. A carton wider than the slot between two guide rails.
    task("infeasible-carton-wider-than-slot",
         "Infeasible: the carton is 500 mm wide and both its sides must touch guide rails that "
         "face each other 400 mm apart.",
         "guide_rails", {
             "left_rail": plane([0, 0, 0], Y_),
             "right_rail": plane([0, 0.4, 0], [0, -1, 0]),
             "conveyor": plane([0, 0, 0], Z)},
         "carton", {
             "left_face": plane([0, -0.25, 0.1], [0, -1, 0]),
             "right_face": plane([0, 0.25, 0.1], Y_),
             "bottom": plane([0, 0, 0], DOWN)},
         [con("coincident", "conveyor", "bottom", "carton on the conveyor",
              orientation="opposed"),
          con("coincident", "left_rail", "left_face", "left side against the left rail",
              orientation="opposed"),
          con("coincident", "right_rail", "right_face", "right side against the right rail",
              orientation="opposed")],
         near=Pose(rpy(0, 0, 0), [0.3, 0.2, 0]))

    # 9. Two grasp-height ranges on the can that do not overlap.
    task("infeasible-can-grasp-height-above-top",
         "Infeasible: the TCP must be 130-160 mm above the table but at least 10 mm below the "
         "top of the 115 mm can, i.e. at most 105 mm up.",
         "soda_can", {
             "axis": line([0.45, -0.12, 0], Z),
             "table": plane([0.45, -0.12, 0], Z),
             "lid": plane([0.45, -0.12, 0.115], Z)},
         "gripper", {
             "tcp": pt(0, 0, 0.15),
             "approach": line([0, 0, 0], Z)},
         [con("coincident", "axis", "tcp", "TCP on the can axis"),
          con("perpendicular", "axis", "approach", "approach from the side"),
          con("distance", "table", "tcp", "grasp 130-160 mm up", min=0.13, max=0.16),
          con("distance", "lid", "tcp", "at least 10 mm below the lid", max=-0.01)],
         near=place(frame(X_, Z), [0, 0, 0.15], [0.45, -0.12, 0.1]))


# ---------------------------------------------------------------------------------------------
# Writing.


def num(x):
    if isinstance(x, float) and x.is_integer() and abs(x) < 1e15:
        return int(x)
    return x


def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items()}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return num(v)


def dumps_spec(spec):
    """The spec laid out as an engineer writes it: one feature, one constraint per line."""
    d = lambda v: json.dumps(clean(v))
    lines = ["{", f'  "relpos": 1,', f'  "name": {d(spec["name"])},',
             f'  "units": {d(spec["units"])},']
    for role in ("fixed", "mobile"):
        obj = spec[role]
        lines.append(f'  "{role}": {{')
        lines.append(f'    "name": {d(obj["name"])},')
        if obj.get("pose") is not None:
            lines.append(f'    "pose": {d(obj["pose"])},')
        lines.append('    "features": {')
        feats = list(obj["features"].items())
        for i, (k, v) in enumerate(feats):
            lines.append(f'      {d(k)}: {d(v)}' + ("," if i + 1 < len(feats) else ""))
        lines.append("    }")
        lines.append("  },")
    lines.append('  "constraints": [')
    cs = spec["constraints"]
    for i, c in enumerate(cs):
        lines.append(f"    {d(c)}" + ("," if i + 1 < len(cs) else ""))
    lines.append("  ]")
    lines.append("}")
    return "\n".join(lines) + "\n"


def build():
    del TASKS[:]
    grasps()
    welding()
    assembly()
    painting_dispensing()
    inspection()
    deburr_screw_pallet()
    infeasible()
    names = [s["name"] for s, _, _ in TASKS]
    assert len(names) == len(set(names)), "duplicate task names"
    for spec, xstar, _ in TASKS:
        assert 2 <= len(spec["constraints"]) <= 6, spec["name"]
        assert all(c.get("id") for c in spec["constraints"]), spec["name"]
    return TASKS


def quat(R):
    """The quaternion [x, y, z, w] of a rotation matrix (w >= 0)."""
    tr = R[0][0] + R[1][1] + R[2][2]
    cands = [(1 + tr, 3), (1 + R[0][0] - R[1][1] - R[2][2], 0),
             (1 - R[0][0] + R[1][1] - R[2][2], 1), (1 - R[0][0] - R[1][1] + R[2][2], 2)]
    _, k = max(cands)
    if k == 3:
        w = math.sqrt(1 + tr) / 2
        q = [(R[2][1] - R[1][2]) / (4 * w), (R[0][2] - R[2][0]) / (4 * w),
             (R[1][0] - R[0][1]) / (4 * w), w]
    elif k == 0:
        x = math.sqrt(1 + R[0][0] - R[1][1] - R[2][2]) / 2
        q = [x, (R[0][1] + R[1][0]) / (4 * x), (R[0][2] + R[2][0]) / (4 * x),
             (R[2][1] - R[1][2]) / (4 * x)]
    elif k == 1:
        y = math.sqrt(1 - R[0][0] + R[1][1] - R[2][2]) / 2
        q = [(R[0][1] + R[1][0]) / (4 * y), y, (R[1][2] + R[2][1]) / (4 * y),
             (R[0][2] - R[2][0]) / (4 * y)]
    else:
        z = math.sqrt(1 - R[0][0] - R[1][1] + R[2][2]) / 2
        q = [(R[0][2] + R[2][0]) / (4 * z), (R[1][2] + R[2][1]) / (4 * z), z,
             (R[1][0] - R[0][1]) / (4 * z)]
    return q if q[3] >= 0 else [-v for v in q]


def quat_to_R(q):
    x, y, z, w = unit4(q)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def unit4(q):
    n = math.sqrt(sum(v * v for v in q))
    return [v / n for v in q]


def run_relpos(binary, path):
    out = subprocess.run([binary, "solve", path], capture_output=True, text=True)
    if out.returncode != 0:
        return None, out.stderr.strip()
    return json.loads(out.stdout), ""


def check_relpos(binary, tasks):
    """Prints relpos's status per task; for solved feasible tasks, whether a branch holds X*."""
    bugs = []
    with tempfile.TemporaryDirectory() as tmp:
        for spec, xstar, _ in tasks:
            name = spec["name"]
            r, err = run_relpos(binary, os.path.join(OUT, name + ".json"))
            if r is None:
                print(f"{name:45s} REJECTED {err[:150]}")
                bugs.append((name, "rejected by the reader"))
                continue
            status, msg = r["status"], r.get("message", "")
            note = ""
            # Every branch's nearest pose must satisfy the constraints (this script's evaluator).
            for b in r.get("branches", []):
                nb = b["nearest"]
                P = Pose(quat_to_R(nb["orientation"]), nb["position"])
                v = math.sqrt(violation(spec, P))
                if v > 1e-6:
                    note += f" [a branch's nearest pose violates the constraints by {v:.3g}]"
                    bugs.append((name, "a returned pose violates the constraints"))
            if xstar is not None and status == "inconsistent":
                bugs.append((name, "feasible task answered inconsistent"))
                note += " [BUG: feasible but inconsistent]"
            if xstar is None and status == "solved":
                bugs.append((name, "infeasible task answered solved"))
                note += " [infeasible but solved]"
            if xstar is not None and status == "solved":
                s2 = json.loads(json.dumps(spec))
                s2["mobile"]["pose"] = {"position": xstar.t, "orientation": quat(xstar.R)}
                p2 = os.path.join(tmp, name + ".json")
                with open(p2, "w") as f:
                    json.dump(s2, f)
                r2, err2 = run_relpos(binary, p2)
                dmin = min((b["nearest"]["distance"] for b in r2.get("branches", [])),
                           default=math.inf) if r2 else math.inf
                if dmin > 1e-6 and not r.get("complete", False):
                    # An incomplete answer (the numeric stage's charts, docs/spec.md section 2.2)
                    # may cover only part of the solutions: not a bug.
                    note += f" [incomplete answer: X* on no branch, nearest distance {dmin:.3g}]"
                elif dmin > 1e-6:
                    bugs.append((name, f"no branch contains X* (nearest distance {dmin:.3g})"))
                    note += f" [BUG: no branch contains X*, nearest distance {dmin:.3g}]"
                else:
                    note += " [X* on a branch]"
            print(f"{name:45s} {'feasible  ' if xstar else 'infeasible'} {status:12s} "
                  f"{msg[:150]}{note}")
    print("bugs:" if bugs else "bugs: none")
    for name, what in bugs:
        print(f"  {name}: {what}")


def main():
    args = sys.argv[1:]
    binary = None
    if args[:1] == ["--check-relpos"] and len(args) == 2:
        binary = args[1]
    elif args:
        raise SystemExit(__doc__)
    tasks = build()
    expected = {}
    for spec, xstar, why in tasks:
        name = spec["name"]
        if xstar is not None:
            R2 = rpy(*to_rpy(xstar.R))
            assert max(abs(R2[i][j] - xstar.R[i][j]) for i in range(3) for j in range(3)) < 1e-12
            check_feasible(spec, xstar)
            expected[name] = {"feasible": True,
                              "pose": {"position": [v + 0.0 for v in xstar.t],
                                       "rpy": [a + 0.0 for a in to_rpy(xstar.R)]},
                              "why": why}
        else:
            least = least_violation(spec)
            if least < 1e-6:
                raise SystemExit(f"{name}: meant infeasible, but a pose violates its "
                                 f"constraints by only {math.sqrt(least):.3g}")
            expected[name] = {"feasible": False, "why": why}
    os.makedirs(OUT, exist_ok=True)
    for spec, _, _ in tasks:
        with open(os.path.join(OUT, spec["name"] + ".json"), "w") as f:
            f.write(dumps_spec(spec))
    with open(os.path.join(OUT, "expected.json"), "w") as f:
        json.dump(expected, f, indent=2)
        f.write("\n")
    nf = sum(1 for v in expected.values() if v["feasible"])
    print(f"wrote {len(tasks)} task specs ({nf} feasible, {len(tasks) - nf} infeasible) and "
          f"expected.json to {os.path.normpath(OUT)}")
    if binary:
        check_relpos(binary, tasks)


if __name__ == "__main__":
    main()
