"""Building a spec in code, as the C++ ``relpos::Problem`` does: objects, named features and
constraints between them. ``Problem.to_dict()`` is the spec of docs/spec.md section 1, so a
Problem is checked, solved and reported exactly as the same spec in a file."""

import math

__all__ = ["Problem", "point", "line", "plane", "cylinder"]


def _vector(v, what):
    values = [float(x) for x in v]
    if len(values) != 3:
        raise ValueError(f"{what}: expected 3 numbers, got {len(values)}")
    return values


def point(p):
    """A point feature at p (in its object's frame)."""
    return {"point": _vector(p, "point")}


def line(p, direction):
    """A directed infinite line through p."""
    return {"line": {"point": _vector(p, "point"), "direction": _vector(direction, "direction")}}


def plane(p, normal):
    """An oriented infinite plane through p."""
    return {"plane": {"point": _vector(p, "point"), "normal": _vector(normal, "normal")}}


def cylinder(p, direction, radius):
    """An infinite cylindrical surface of this radius about the line (p, direction); its axis is
    the feature ``NAME.axis``."""
    return {"cylinder": {"point": _vector(p, "point"), "direction": _vector(direction, "direction"),
                         "radius": float(radius)}}


def _pose(pose):
    """A spec pose from a 4x4 matrix (nested lists or a numpy array) or a spec pose dict."""
    if pose is None or isinstance(pose, dict):
        return pose
    rows = [[float(x) for x in row] for row in pose]
    if len(rows) != 4 or any(len(r) != 4 for r in rows):
        raise ValueError("a pose is a 4x4 homogeneous matrix or a spec pose dict")
    return {"matrix": rows}


class Problem:
    """A fixed object, a mobile object (at its initial pose), features on both and constraints
    between them. Methods return the Problem, so calls chain."""

    def __init__(self, name="problem", *, angle_unit="rad", length_unit=None):
        self.name = name
        self.units = {"angle": angle_unit}
        if length_unit is not None:
            self.units["length"] = length_unit
        self._objects = {"fixed": {"name": "fixed", "features": {}},
                         "mobile": {"name": "mobile", "features": {}}}
        self.constraints = []
        self.obstacles = []
        self.allowed_contacts = []

    def _object(self, which, name, pose, mesh, clearance=None, mesh_scale=None):
        o = self._objects[which]
        if mesh_scale is not None:
            o["mesh_scale"] = float(mesh_scale)
        if clearance is not None:
            o["clearance"] = float(clearance)
        if name is not None:
            o["name"] = name
        if pose is not None:
            o["pose"] = _pose(pose)
        if mesh is not None:
            o["mesh"] = str(mesh)
        return self

    def set_fixed(self, name=None, *, pose=None, mesh=None, clearance=None, mesh_scale=None):
        """The fixed object's name, pose in the world, mesh (for collision filtering; its
        coordinates times mesh_scale) and own clearance (in place of the solve's)."""
        return self._object("fixed", name, pose, mesh, clearance, mesh_scale)

    def set_mobile(self, name=None, *, pose=None, mesh=None, mesh_scale=None):
        """The mobile object's name, initial pose (where it is now) and mesh."""
        return self._object("mobile", name, pose, mesh, None, mesh_scale)

    def add_obstacle(self, name, mesh, *, pose=None, clearance=None, mesh_scale=None):
        o = {"name": name, "mesh": str(mesh)}
        if mesh_scale is not None:
            o["mesh_scale"] = float(mesh_scale)
        if pose is not None:
            o["pose"] = _pose(pose)
        if clearance is not None:
            o["clearance"] = float(clearance)
        self.obstacles.append(o)
        return self

    def allow_contact(self, name):
        """The mobile object may touch or pass into this object (the fixed one or an obstacle):
        it is left out of collision filtering."""
        self.allowed_contacts.append(name)
        return self

    def add_fixed_feature(self, name, feature):
        """A feature of the fixed object: point(...), line(...), plane(...) or cylinder(...)."""
        self._objects["fixed"]["features"][name] = feature
        return self

    def add_mobile_feature(self, name, feature):
        self._objects["mobile"]["features"][name] = feature
        return self

    def add_constraint(self, type, fixed, mobile, value=None, *, min=None, max=None,
                       orientation="aligned", parallel=None, id=None):
        """A constraint between the fixed feature ``fixed`` and the mobile feature ``mobile``:
        an exact ``value``, or a range ``min``/``max`` (one of them alone: open on the other
        side), angles in the problem's angle unit. ``orientation``: aligned, opposed or either;
        ``parallel=False``: a line-line distance measured between skew lines."""
        c = {"type": type, "fixed": fixed, "mobile": mobile}
        if value is not None:
            c["value"] = float(value)
        for key, bound in (("min", min), ("max", max)):
            if bound is not None and not math.isinf(float(bound)):
                c[key] = float(bound)
        if orientation != "aligned":
            c["orientation"] = orientation
        if parallel is not None:
            c["parallel"] = bool(parallel)
        if id is not None:
            c["id"] = str(id)
        self.constraints.append(c)
        return self

    def to_dict(self):
        """The spec (docs/spec.md section 1) as a dict."""
        spec = {"relpos": 1, "name": self.name, "units": dict(self.units),
                "fixed": self._objects["fixed"], "mobile": self._objects["mobile"],
                "constraints": list(self.constraints)}
        if self.obstacles:
            spec["obstacles"] = list(self.obstacles)
        if self.allowed_contacts:
            spec["allowed_contacts"] = list(self.allowed_contacts)
        return spec

    def solve(self, samples=0, collision=False, **options):
        """Solves it: a relpos.Solution (options as relpos.solve's)."""
        from . import Solution

        return Solution(self, samples, collision, **options)
