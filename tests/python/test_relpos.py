"""The Python package against the command line and the tests' evaluator (pose_check, written from
docs/spec.md alone). Run by ctest with Debian's python3; the environment names the tools:
RELPOS_CLI (the relpos command), RELPOS_POSE_CHECK and RELPOS_SOURCE_DIR."""

import glob
import json
import math
import os
import subprocess
import tempfile
import unittest
import warnings

import numpy as np

import relpos

SOURCE = os.environ["RELPOS_SOURCE_DIR"]
CLI = os.environ["RELPOS_CLI"]
POSE_CHECK = os.environ["RELPOS_POSE_CHECK"]
# Violations are lengths and angles mixed; the bundled specs are about a unit in size.
TOLERANCE = 1e-6


def spec_files(folder):
    return sorted(glob.glob(os.path.join(SOURCE, "data", folder, "*.json")))


def without_timing(result):
    result = dict(result)
    result.pop("stats", None)
    return result


def cli_result(path, *args):
    out = subprocess.run([CLI, "solve", path, *args], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def violations(spec_path, poses):
    """The evaluator's worst violation at each 4x4 pose."""
    lines = "".join(" ".join(repr(float(x)) for x in np.asarray(X).reshape(16)) + "\n"
                    for X in poses)
    out = subprocess.run([POSE_CHECK, spec_path], input=lines, capture_output=True, text=True,
                         check=True)
    return [float(line.split()[0]) for line in out.stdout.splitlines()]


def pose_matrix(position, orientation):
    """A 4x4 matrix from the result's position and quaternion (x, y, z, w)."""
    x, y, z, w = orientation
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    X = np.eye(4)
    X[:3, :3] = R
    X[:3, 3] = position
    return X


class SolveTest(unittest.TestCase):
    def test_every_bundled_spec_gives_the_command_lines_document(self):
        files = spec_files("examples") + spec_files("scenarios")
        self.assertGreater(len(files), 50)
        for path in files:
            with self.subTest(spec=os.path.basename(path)):
                self.assertEqual(without_timing(relpos.solve(path)),
                                 without_timing(cli_result(path)))

    def test_samples_and_collision_options_reach_the_report(self):
        path = os.path.join(SOURCE, "data", "collision", "part-on-table-beside-wall.json")
        got = relpos.solve(path, samples=3, collision=True, seed=7, clearance=0.01)
        want = cli_result(path, "--samples", "3", "--collision", "--seed", "7",
                          "--clearance", "0.01")
        self.assertEqual(without_timing(got), without_timing(want))
        self.assertTrue(any("collision" in b for b in got["branches"]))
        self.assertEqual(len(got["branches"][0]["samples"]), 3)

    def test_angles_in_degrees_as_the_command_line_writes_them(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-b-seam-welding.json")
        got = relpos.solve(path, samples=2, angles="deg")
        self.assertEqual(without_timing(got),
                         without_timing(cli_result(path, "--samples", "2", "--angles", "deg")))
        self.assertEqual(got["units"], {"angle": "deg"})
        with self.assertRaises(ValueError):
            relpos.solve(path, angles="grad")

    def test_a_dicts_meshes_are_found_from_base_dir_and_contacts_may_be_allowed(self):
        folder = os.path.join(SOURCE, "data", "collision")
        with open(os.path.join(folder, "part-on-table-beside-wall.json")) as f:
            spec = json.load(f)
        spec["allowed_contacts"] = ["table"]
        got = relpos.solve(spec, collision=True, clearance=0.01, base_dir=folder)
        self.assertEqual(got["branches"][0]["collision"]["checked_against"], ["wall"])
        with self.assertRaises(relpos.SpecError) as e:  # no base_dir: the meshes are not found
            relpos.solve(spec, collision=True)
        self.assertEqual(e.exception.path, "mobile.mesh")

    def test_a_dict_is_solved_as_the_same_spec_in_a_file(self):
        for path in spec_files("scenarios"):
            with open(path) as f:
                spec = json.load(f)
            spec.setdefault("name", os.path.splitext(os.path.basename(path))[0])
            with self.subTest(spec=os.path.basename(path)):
                self.assertEqual(without_timing(relpos.solve(spec)),
                                 without_timing(relpos.solve(path)))

    def test_numpy_values_in_a_dict_are_numbers(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-a-plane-distance.json")
        with open(path) as f:
            spec = json.load(f)
        mobile = spec["mobile"]
        mobile["pose"] = {"position": np.array(mobile.get("pose", {}).get("position", [0, 0, 0]),
                                               dtype=float)}
        plain = json.loads(json.dumps(spec, default=lambda a: a.tolist()))
        self.assertEqual(without_timing(relpos.solve(spec)), without_timing(relpos.solve(plain)))


class BranchTest(unittest.TestCase):
    def solved_examples(self):
        for path in spec_files("examples") + spec_files("scenarios"):
            solution = relpos.Solution(path)
            if solution.status == "solved":
                yield path, solution

    def test_every_sampled_pose_satisfies_the_spec(self):
        checked = 0
        for path, solution in self.solved_examples():
            for branch in solution.branches:
                params, poses = branch.sample(16, seed=3)
                self.assertEqual(params.shape, (16, branch.dof))
                self.assertEqual(poses.shape, (16, 4, 4))
                worst = max(violations(path, poses))
                with self.subTest(spec=os.path.basename(path), branch=branch.index):
                    self.assertLessEqual(worst, TOLERANCE)
                # pose(θ) gives the sample's pose back
                for t, X in zip(params[:3], poses[:3]):
                    np.testing.assert_allclose(branch.pose(t), X, atol=1e-12)
                checked += 1
        self.assertGreater(checked, 60)

    def test_the_nearest_parameters_give_the_documents_nearest_pose(self):
        for path, solution in self.solved_examples():
            for branch in solution.branches:
                near = branch.result["nearest"]
                X = branch.pose(branch.nearest_parameters)
                want = pose_matrix(near["position"], near["orientation"])
                with self.subTest(spec=os.path.basename(path), branch=branch.index):
                    np.testing.assert_allclose(X, want, atol=1e-9)

    def test_the_nearest_pose_to_a_pose_of_the_branch_is_that_pose(self):
        for path, solution in self.solved_examples():
            for branch in solution.branches:
                _, poses = branch.sample(2, seed=11)
                for X in poses:
                    n = branch.nearest(X)
                    with self.subTest(spec=os.path.basename(path), branch=branch.index):
                        self.assertLess(n["distance"], 1e-6)
                        np.testing.assert_allclose(n["pose"], X, atol=1e-6)
                        self.assertEqual(len(n["parameters"]), branch.dof)
                        # On an exact branch the pose is its own projection: proven nearest.
                        if branch.result["exact"]:
                            self.assertTrue(n["global"])

    def test_the_nearest_pose_is_no_farther_than_any_sample(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-c-cylinder-grasp.json")
        solution = relpos.Solution(path)
        target = np.eye(4)
        target[:3, 3] = [0.3, -0.2, 0.5]
        for branch in solution.branches:
            n = branch.nearest(target)
            _, poses = branch.sample(200, seed=5)
            for X in poses:
                d = np.linalg.norm(X[:3, 3] - target[:3, 3]) + rotation_angle(X[:3, :3].T)
                self.assertGreaterEqual(d, n["distance"] - 1e-9)

    def test_parameters_describe_the_bounds(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-d-soda-can-grasp.json")
        solution = relpos.Solution(path)
        for branch, doc in zip(solution.branches, solution.result["branches"]):
            self.assertEqual(len(branch.parameters), branch.dof)
            for mine, theirs in zip(branch.parameters, doc["parameters"]):
                self.assertEqual(mine["name"], theirs["name"])
                self.assertEqual(mine["kind"], theirs["kind"])
                for key in ("min", "max"):
                    want = theirs[key]
                    if want is None:
                        self.assertTrue(math.isinf(mine[key]))
                    else:
                        self.assertEqual(mine[key], want)

    def test_bad_parameters_and_poses_are_value_errors(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-d-soda-can-grasp.json")
        branch = relpos.Solution(path).branches[0]
        with self.assertRaises(ValueError):
            branch.pose([0.0] * (branch.dof + 1))
        with self.assertRaises(ValueError):
            branch.pose([math.nan] * branch.dof)
        bounded = [i for i, p in enumerate(branch.parameters)
                   if not p["periodic"] and math.isfinite(p["max"])]
        self.assertTrue(bounded)
        t = list(branch.nearest_parameters)
        t[bounded[0]] = branch.parameters[bounded[0]]["max"] + 1.0
        with self.assertRaisesRegex(ValueError, "outside its bounds"):
            branch.pose(t)
        sheared = np.eye(4)
        sheared[0, 1] = 0.5
        with self.assertRaisesRegex(ValueError, "rotation"):
            branch.nearest(sheared)


def rotation_angle(R):
    return math.acos(max(-1.0, min(1.0, (np.trace(R) - 1.0) / 2.0)))


class ErrorTest(unittest.TestCase):
    def spec(self):
        return (relpos.Problem("bad")
                .add_fixed_feature("top", relpos.problem.plane([0, 0, 0], [0, 0, 1]))
                .add_mobile_feature("tcp", relpos.problem.point([0, 0, 0])))

    def test_an_unknown_type_names_its_json_path_and_suggests_nothing_wrong(self):
        p = self.spec().add_constraint("coincidence", "top", "tcp", id="rest")
        with self.assertRaises(relpos.SpecError) as e:
            relpos.solve(p)
        self.assertEqual(e.exception.path, "constraints[0].type")
        self.assertIn("coincidence", e.exception.message)
        self.assertEqual(e.exception.file, "<dict>")
        self.assertIn("constraints[0].type", str(e.exception))

    def test_an_unknown_feature_is_a_spec_error(self):
        p = self.spec().add_constraint("coincident", "top", "tcp2")
        with self.assertRaises(relpos.SpecError) as e:
            relpos.solve(p)
        self.assertEqual(e.exception.path, "constraints[0].mobile")

    def test_a_bad_file_names_the_file(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "broken.json")
            with open(path, "w") as f:
                f.write('{"fixed": {"features": {}}, "mobile": {"features": {}}, '
                        '"constraints": [{"type": "distance"}]}')
            with self.assertRaises(relpos.SpecError) as e:
                relpos.solve(path)
            self.assertEqual(e.exception.file, path)
            self.assertTrue(e.exception.path.startswith("constraints[0]"))

    def test_a_missing_file_and_a_wrong_type_are_refused(self):
        with self.assertRaises(ValueError):
            relpos.solve("/no/such/spec.json")
        with self.assertRaises(TypeError):
            relpos.solve(42)

    def test_warnings_are_python_warnings(self):
        p = self.spec().add_constraint("coincident", "top", "tcp")
        spec = p.to_dict()
        spec["colour"] = "red"
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = relpos.solve(spec)
        self.assertEqual(result["status"], "solved")
        self.assertTrue(any("colour" in str(w.message) for w in caught))


class ProblemTest(unittest.TestCase):
    def test_a_built_problem_is_its_spec(self):
        p = (relpos.Problem("peg", angle_unit="deg")
             .set_fixed("plate")
             .set_mobile("peg", pose=np.array([[1, 0, 0, 0.1], [0, 1, 0, 0.2], [0, 0, 1, 0.3],
                                               [0, 0, 0, 1]]))
             .add_fixed_feature("hole", relpos.problem.line([0, 0, 0], [0, 0, 1]))
             .add_fixed_feature("face", relpos.problem.plane([0, 0, 0], [0, 0, 1]))
             .add_mobile_feature("axis", relpos.problem.line([0, 0, 0], [0, 0, 1]))
             .add_mobile_feature("tip", relpos.problem.point([0, 0, -0.05]))
             .add_constraint("coincident", "hole", "axis", id="in the hole")
             .add_constraint("distance", "face", "tip", min=-0.04, max=-0.01, id="depth"))
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "peg.json")
            with open(path, "w") as f:
                json.dump(p.to_dict(), f)
            want = cli_result(path)
            solution = p.solve()
            self.assertEqual(without_timing(solution.as_dict()), without_timing(want))
            self.assertEqual(solution.status, "solved")
            for branch in solution.branches:
                _, poses = branch.sample(20)
                self.assertLessEqual(max(violations(path, poses)), TOLERANCE)
            # the range is a parameter with the spec's bounds (metres)
            names = [q["name"] for q in solution.branches[0].parameters]
            self.assertIn("distance", names)

    def test_an_infeasible_problem_is_inconsistent(self):
        p = (relpos.Problem("apart")
             .add_fixed_feature("a", relpos.problem.point([0, 0, 0]))
             .add_fixed_feature("b", relpos.problem.point([1, 0, 0]))
             .add_mobile_feature("p", relpos.problem.point([0, 0, 0]))
             .add_constraint("distance", "a", "p", 0.2, id="near a")
             .add_constraint("distance", "b", "p", 0.3, id="near b"))
        solution = p.solve()
        self.assertEqual(solution.status, "inconsistent")
        self.assertTrue(solution.complete)
        self.assertEqual(solution.branches, [])
        self.assertIsNone(solution.best)
        self.assertIn("near a", solution.message)

    def test_a_feature_needs_three_coordinates(self):
        with self.assertRaises(ValueError):
            relpos.problem.point([0, 0])


def xform(b):
    """TSR's Xform(b): translation (x, y, z) times Rz(yaw) Ry(pitch) Rx(roll)."""
    x, y, z, roll, pitch, yaw = b
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    X = np.eye(4)
    X[:3, :3] = (np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
                 @ np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
                 @ np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]]))
    X[:3, 3] = [x, y, z]
    return X


class PlannerAndPictureTest(unittest.TestCase):
    def test_every_pose_drawn_from_a_tsr_chain_satisfies_the_spec(self):
        rng = np.random.default_rng(3)
        for name in ("scenario-c-cylinder-grasp", "scenario-d-soda-can-grasp"):
            path = os.path.join(SOURCE, "data", "scenarios", name + ".json")
            for branch in relpos.Solution(path).branches:
                tsr = branch.tsr(window=0.3)
                self.assertTrue(tsr["exact"], tsr["why"])
                poses = []
                for _ in range(50):
                    X = np.eye(4)
                    for link in tsr["tsr_chain"]:
                        Bw = link["Bw"]
                        self.assertEqual(Bw.shape, (6, 2))
                        b = Bw[:, 0] + (Bw[:, 1] - Bw[:, 0]) * rng.random(6)
                        X = X @ link["T0_w"] @ xform(b) @ link["Tw_e"]
                    poses.append(X)
                self.assertLessEqual(max(violations(path, poses)), 1e-9, name)
        with self.assertRaises(ValueError):
            relpos.Solution(path).branches[0].tsr(window=0)

    def test_view_writes_the_page(self):
        path = os.path.join(SOURCE, "data", "scenarios", "scenario-d-soda-can-grasp.json")
        solution = relpos.Solution(path)
        with tempfile.TemporaryDirectory() as d:
            page = solution.view(os.path.join(d, "can.html"), samples=2, angles="deg")
            with open(page, encoding="utf-8") as f:
                text = f.read()
        start = text.index('type="application/json">') + len('type="application/json">')
        scene = json.loads(text[start:text.index("</script>", start)])
        self.assertEqual(len(scene["branches"]), len(solution.branches))
        self.assertEqual(scene["angles"], "deg")
        self.assertTrue(all(len(b["samples"]) == 2 for b in scene["branches"]))
        for bad in ({"angles": "grad"}, {"samples": -1}, {"window": float("nan")}):
            with self.assertRaises(ValueError, msg=str(bad)):
                solution.view(os.path.join(d, "x.html"), **bad)


class ExampleTest(unittest.TestCase):
    def test_the_readme_example_prints_a_valid_grasp_pose(self):
        script = os.path.join(SOURCE, "examples", "python", "grasp.py")
        with tempfile.TemporaryDirectory() as d:
            page = os.path.join(d, "grasp.html")
            out = subprocess.run([os.environ.get("PYTHON", "python3"), script, page],
                                 capture_output=True, text=True, check=True, env=dict(os.environ))
            with open(page, encoding="utf-8") as f:
                self.assertTrue(f.read().startswith("<!DOCTYPE html>"))
        lines = out.stdout.splitlines()
        self.assertTrue(lines[0].startswith("status: solved"), out.stdout)
        self.assertRegex(out.stdout, r"TSR chain: [1-6] link\(s\)")
        self.assertIn("picture: " + page, out.stdout)
        # the example's last four lines: the grasp pose, a 4x4 matrix
        X = np.array([[float(v) for v in line.split()] for line in lines[-4:]])
        self.assertEqual(X.shape, (4, 4))
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "grasp.json")
            with open(path, "w") as f:
                f.write(json.dumps(grasp_spec(script)))
            self.assertLessEqual(violations(path, [X])[0], 1e-6)


    def test_the_readme_shows_the_example_as_it_is(self):
        with open(os.path.join(SOURCE, "README.md")) as f:
            readme = f.read()
        section = readme[readme.index("## Python"):]
        block = section[section.index("```python\n") + len("```python\n"):]
        block = block[:block.index("```\n")]
        with open(os.path.join(SOURCE, "examples", "python", "grasp.py")) as f:
            code = f.read()
        body = code[code.index('"""', 3) + 4:]  # after the module's docstring
        self.assertEqual(block, body)


def grasp_spec(script):
    """The spec the example builds (it exposes it as grasp_problem())."""
    namespace = {"__name__": "example"}
    with open(script) as f:
        exec(compile(f.read(), script, "exec"), namespace)
    return namespace["grasp_problem"]().to_dict()


if __name__ == "__main__":
    unittest.main()
