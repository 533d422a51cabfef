"""relpos for Python: every pose of a mobile object that satisfies geometric relations.

    import relpos
    result = relpos.solve("grasp.json")            # the result document as a dict
    solution = relpos.Solution("grasp.json")       # the same, with branch objects
    branch = solution.branches[0]
    X = branch.pose(branch.nearest_parameters)     # a 4x4 numpy array
    params, poses = branch.sample(10)

A spec is a path to a spec file (docs/spec.md section 1) or a dict of the same content (a
``Problem`` builds one). Bad input raises ``SpecError`` naming the JSON path, as the command line's
exit-2 message does. Results are those of ``relpos solve`` (docs/spec.md section 2).
"""

import json
import math
import os
import warnings

from . import _relpos
from .problem import Problem

__all__ = ["solve", "Solution", "Branch", "Problem", "SpecError", "load_plugin", "__version__"]

__version__ = _relpos.__version__
# Plugins named without a path are looked for beside the package (docs/spec.md section 4.1).
_relpos.set_program_dir(os.path.dirname(os.path.abspath(__file__)))


class SpecError(ValueError):
    """A spec relpos cannot read: ``file``, ``path`` (the JSON path of the first problem, e.g.
    ``constraints[2].type``), ``message``, and ``errors``: every (path, message) found."""

    def __init__(self, file, errors):
        self.file = file
        self.errors = list(errors)
        self.path, self.message = self.errors[0] if self.errors else ("", "invalid spec")
        where = f"{self.path}: " if self.path else ""
        super().__init__(f"{file}: {where}{self.message}")


def load_plugin(path):
    """Loads a plugin library (docs/spec.md section 4) for every later solve: a path, or the name
    of an installed one ("symmetric"); RuntimeError naming the file when it cannot be loaded. A
    spec's own ``plugins`` list is loaded by the solve."""
    _relpos.load_plugin(os.fspath(path))


def _json_default(value):
    # numpy arrays and scalars, written as JSON numbers and lists
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not a JSON value")


def _solve(spec, samples, window, seed, collision, clearance, collision_samples, base_dir,
           angles="rad"):
    if angles not in ("rad", "deg"):
        raise ValueError(f"angles: expected 'deg' or 'rad', got {angles!r}")
    options = _relpos.SolveOptions()
    options.degrees = angles == "deg"
    options.samples = int(samples)
    options.window = float(window)
    options.seed = int(seed)
    options.collision = bool(collision)
    options.clearance = float(clearance)
    options.collision_samples = int(collision_samples)
    if isinstance(spec, Problem):
        spec = spec.to_dict()
    if isinstance(spec, dict):
        file = "<dict>"
        try:
            text = json.dumps(spec, default=_json_default, allow_nan=False)
        except ValueError:  # NaN or an infinity: JSON has no such number
            raise SpecError(file, [("", "a number is NaN or infinite (JSON has no such number)")])
        solved, errors, found = _relpos.solve_text(text, os.fspath(base_dir or "."), options)
    elif isinstance(spec, (str, os.PathLike)):
        file = os.fspath(spec)
        solved, errors, found = _relpos.solve_file(file, options)
    else:
        raise TypeError("a spec is a path or a dict, not " + type(spec).__name__)
    for path, message in found:
        where = f"{path}: " if path else ""
        warnings.warn(f"{file}: {where}{message}", stacklevel=3)
    if solved is None:
        raise SpecError(file, errors)
    return solved


def solve(spec, samples=0, collision=False, *, window=1.0, seed=0, clearance=0.0,
          collision_samples=64, base_dir=None, angles="rad"):
    """Solves a spec (a path or a dict) and returns the result document of ``relpos solve`` as a
    dict. ``samples``: poses per branch; ``collision``: filter against the meshes (paths relative
    to the spec file, or to ``base_dir`` for a dict, default the current folder); ``angles``:
    "deg" writes the document's angles in degrees; the other options are the command line's
    (docs/spec.md section 3.2)."""
    solved = _solve(spec, samples, window, seed, collision, clearance, collision_samples,
                    base_dir, angles)
    return json.loads(solved.json)


class Branch:
    """One solution branch: a set of poses X(theta) over its parameters' bounds."""

    def __init__(self, ref, result):
        self._ref = ref
        self._result = result

    @property
    def index(self):
        return self._ref.index

    @property
    def dof(self):
        return self._ref.dof

    @property
    def exact(self):
        """True for a closed form; False for a certified numeric branch (see ``certified``)."""
        return self._ref.exact

    @property
    def manifold(self):
        return self._ref.manifold

    @property
    def parameters(self):
        """One dict per parameter: name, kind (angle, length, other), min, max, periodic; an
        unbounded length has min -inf / max inf."""
        return self._ref.parameters

    @property
    def nearest_parameters(self):
        """The parameters of the branch's pose nearest the mobile object's initial pose."""
        return list(self._result["nearest"]["parameters"])

    @property
    def result(self):
        """This branch's entry of the result document."""
        return self._result

    def pose(self, parameters=()):
        """The pose X_WM at these parameters, a 4x4 numpy array; ValueError for a wrong count, a
        non-finite value or one outside a bounded parameter's range."""
        return self._ref.pose([float(p) for p in parameters])

    def nearest(self, pose):
        """The branch's pose nearest to ``pose`` (a 4x4 homogeneous matrix): a dict with
        ``parameters``, ``pose`` (4x4), ``distance`` (translation plus rotation angle) and
        ``global`` (True where the pose is proven the nearest of the whole branch)."""
        import numpy as np

        return self._ref.nearest(np.asarray(pose, dtype=float))

    def sample(self, n, *, window=1.0, seed=0):
        """n poses drawn uniformly within the parameters' bounds (an unbounded length within
        +-window of the nearest pose's): (parameters as an n x dof array, poses as n x 4 x 4)."""
        return self._ref.sample(int(n), float(window), int(seed))

    def tsr(self, *, window=1.0):
        """The branch as a Task Space Region chain (docs/spec.md section 3.11): a dict with
        ``exact``, ``why`` (None when exact), ``tsr_chain`` (None, or one dict per link with 4x4
        ``T0_w`` and ``Tw_e`` and the 6x2 bounds ``Bw``: x, y, z, roll, pitch, yaw) and, when an
        unbounded length was bounded to +-window, ``window``."""
        return self._ref.tsr(float(window))

    def __repr__(self):
        return f"<relpos.Branch {self.index}: {self.dof} DOF, {self.manifold}>"


class Solution:
    """A solved spec: the result document's fields, and ``branches`` as Branch objects whose
    poses can be asked for. The arguments are ``solve``'s but ``angles``: a Branch works in
    radians, and so does its ``result``."""

    def __init__(self, spec, samples=0, collision=False, *, window=1.0, seed=0, clearance=0.0,
                 collision_samples=64, base_dir=None):
        self._solved = _solve(spec, samples, window, seed, collision, clearance,
                              collision_samples, base_dir)
        self.result = json.loads(self._solved.json)
        documents = self.result.get("branches", [])
        self.branches = [Branch(self._solved.branch(i), documents[i])
                         for i in range(self._solved.branch_count)]

    @property
    def status(self):
        """solved, inconsistent or unhandled (docs/spec.md section 2.3)."""
        return self.result["status"]

    @property
    def complete(self):
        return self.result["complete"]

    @property
    def message(self):
        return self.result["message"]

    @property
    def best(self):
        """The branch whose nearest pose is nearest the initial pose, or None."""
        b = self.result.get("best")
        return None if b is None else self.branches[b]

    def as_dict(self):
        return json.loads(self._solved.json)

    def view(self, path, *, samples=12, window=None, angles="rad"):
        """Writes the page ``relpos view`` writes (docs/spec.md section 3.12) to ``path``: the
        objects, each branch's nearest pose, ``samples`` ghosts per branch and a slider per
        parameter; unbounded lengths within +-window (default: the problem's size). Returns
        ``path``."""
        if angles not in ("rad", "deg"):
            raise ValueError("angles: 'rad' or 'deg'")
        if int(samples) < 0:
            raise ValueError("the number of samples must be >= 0")
        if window is None:
            window = self._solved.size
        if not (math.isfinite(float(window)) and float(window) >= 0):
            raise ValueError("window must be a finite number >= 0")
        page = self._solved.page(int(samples), float(window), angles == "deg")
        with open(path, "w", encoding="utf-8") as out:
            out.write(page)
        return path

    def __repr__(self):
        return f"<relpos.Solution {self.status}: {len(self.branches)} branches>"
