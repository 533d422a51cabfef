"""Grasping a soda can from the side, in Python (README, "Python").

The gripper's tool centre point (TCP) must be on the can's axis, its approach axis (z)
horizontal, meeting the can's axis at a right angle, and the TCP between 3 and 9 cm above the
table. relpos returns every such pose; this prints the branch nearest to where the gripper is now,
its Task Space Region chain (for a planner), writes a picture of every branch (grasp.html, or the
path given) and prints the nearest pose.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/grasp.py
"""
import sys

import numpy as np

import relpos
from relpos.problem import line, plane, point


def grasp_problem():
    gripper_now = np.eye(4)
    gripper_now[:3, 3] = [0.30, 0.10, 0.25]  # where the gripper is (metres)
    return (relpos.Problem("can-side-grasp", angle_unit="deg", length_unit="m")
            .set_fixed("table")
            .set_mobile("gripper", pose=gripper_now)
            .add_fixed_feature("can_axis", line([0.5, 0.0, 0.0], [0, 0, 1]))
            .add_fixed_feature("table_top", plane([0, 0, 0], [0, 0, 1]))
            .add_mobile_feature("tcp", point([0, 0, 0]))
            .add_mobile_feature("approach", line([0, 0, 0], [0, 0, 1]))
            .add_constraint("coincident", "can_axis", "tcp", id="centred")
            .add_constraint("perpendicular", "can_axis", "approach", id="from the side")
            .add_constraint("distance", "table_top", "tcp", min=0.03, max=0.09, id="height"))


if __name__ == "__main__":
    solution = grasp_problem().solve()
    print(f"status: {solution.status}, {len(solution.branches)} branch(es)")
    best = solution.best
    for p in best.parameters:
        print(f"  parameter {p['name']}: {p['kind']} in [{p['min']:.3f}, {p['max']:.3f}]")
    tsr = best.tsr()  # for a planner: T0_w . Xform(b) . Tw_e per link, b within Bw
    print(f"TSR chain: {len(tsr['tsr_chain'])} link(s)" if tsr["exact"] else f"no TSR: {tsr['why']}")
    for link in tsr["tsr_chain"] or []:
        print("  Bw (x y z roll pitch yaw):", np.round(link["Bw"], 4).tolist())
    print("picture:", solution.view(sys.argv[1] if len(sys.argv) > 1 else "grasp.html"))
    print(f"nearest pose, {best.result['nearest']['distance']:.3f} from the gripper's:")
    for row in best.pose(best.nearest_parameters):
        print(" ".join(f"{v:.12f}" for v in row))
