// relpos export (docs/spec.md §3.11): a spec's branches in a planner's terms — TSR chains or
// MoveIt goal constraints.
#include <exception>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli.hpp"
#include "output_file.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/report/moveit.hpp"
#include "relpos/report/tsr.hpp"

namespace relpos::cli {
namespace {

nlohmann::json matrix(const relpos::Isometry3d& X) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (int c = 0; c < 4; ++c) row.push_back(X.matrix()(r, c));
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json tsrBranch(const relpos::Problem& pb, const relpos::Branch& b, std::size_t index,
                         double window) {
  nlohmann::json j;
  j["index"] = index;
  j["manifold"] = b.manifold->describe();
  j["dof"] = b.manifold->dof();
  const relpos::NearestPose near = relpos::nearestOnBranch(b, pb.mobile.pose);
  const relpos::TsrExport e = relpos::tsrChainOf(pb, b, near.parameters, window);
  j["exact"] = e.exact;
  if (!e.exact) {
    j["tsr_chain"] = nullptr;
    j["why"] = e.why;
    return j;
  }
  nlohmann::json chain = nlohmann::json::array();
  for (const relpos::TsrLink& l : e.chain) {
    nlohmann::json bw = nlohmann::json::array();
    for (const auto& row : l.Bw) bw.push_back({row[0], row[1]});
    chain.push_back({{"T0_w", matrix(l.T0_w)}, {"Tw_e", matrix(l.Tw_e)}, {"Bw", bw}});
  }
  j["tsr_chain"] = chain;
  if (e.windowed) j["window"] = window;
  return j;
}

nlohmann::json vec(const relpos::Vector3d& v) { return {{"x", v.x()}, {"y", v.y()}, {"z", v.z()}}; }

nlohmann::json quat(const Eigen::Quaterniond& q) {
  return {{"x", q.x()}, {"y", q.y()}, {"z", q.z()}, {"w", q.w()}};
}

// moveit_msgs/Constraints for one branch, frames named as relpos's: "world" and the mobile
// object's name as the link.
nlohmann::json moveitBranch(const relpos::Problem& pb, const relpos::Branch& b, std::size_t index,
                            double window) {
  nlohmann::json j;
  j["index"] = index;
  j["manifold"] = b.manifold->describe();
  j["dof"] = b.manifold->dof();
  const relpos::NearestPose near = relpos::nearestOnBranch(b, pb.mobile.pose);
  const relpos::MoveItGoal g = relpos::moveitGoalOf(pb, b, near.parameters, window);
  j["exact"] = g.exact;
  if (!g.exact) j["why"] = g.why;
  if (g.windowed) j["window"] = window;
  const nlohmann::json header = {{"frame_id", "world"}};
  nlohmann::json position = {
      {"header", header},
      {"link_name", pb.mobile.name},
      {"target_point_offset", vec(g.target_point_offset)},
      {"constraint_region",
       {{"primitives",
         {{{"type", 1},  // shape_msgs/SolidPrimitive BOX
           {"dimensions", {g.box_dimensions.x(), g.box_dimensions.y(), g.box_dimensions.z()}}}}},
        {"primitive_poses",
         {{{"position", vec(g.box_pose.translation())},
           {"orientation", quat(Eigen::Quaterniond(g.box_pose.linear()))}}}},
        {"meshes", nlohmann::json::array()},
        {"mesh_poses", nlohmann::json::array()}}},
      {"weight", 1.0}};
  nlohmann::json orientation = {{"header", header},
                                {"orientation", quat(g.orientation)},
                                {"link_name", pb.mobile.name},
                                {"absolute_x_axis_tolerance", g.axis_tolerances.x()},
                                {"absolute_y_axis_tolerance", g.axis_tolerances.y()},
                                {"absolute_z_axis_tolerance", g.axis_tolerances.z()},
                                {"parameterization", 0},  // XYZ_EULER_ANGLES
                                {"weight", 1.0}};
  j["constraints"] = {{"name", pb.name + " branch " + std::to_string(index)},
                      {"joint_constraints", nlohmann::json::array()},
                      {"position_constraints", {position}},
                      {"orientation_constraints", {orientation}},
                      {"visibility_constraints", nlohmann::json::array()}};
  return j;
}

}  // namespace

int cmdExport(const Args& a, const Registry& reg) {
  if (a.positional.size() != 1) throw UsageError("export takes exactly one spec file");
  if (a.format != "tsr" && a.format != "moveit")
    throw UsageError(a.format.empty() ? "export needs --format tsr or --format moveit"
                                      : "--format: expected tsr or moveit, got '" + a.format + "'");
  if (!a.out.empty()) checkOutput(a.out, a.positional, OutputMode::kReplace);
  relpos::Problem pb;
  if (!loadProblem(a.positional[0], reg, &pb)) return kExitInvalid;
  const relpos::Solution sol = relpos::solve(pb, reg);
  nlohmann::json doc;
  doc["relpos"] = 1;
  doc["name"] = pb.name;
  doc["format"] = a.format;
  doc["status"] = relpos::toString(sol.status);
  doc["message"] = sol.message;
  nlohmann::json branches = nlohmann::json::array();
  for (std::size_t i = 0; i < sol.branches.size(); ++i) {
    try {
      branches.push_back(a.format == "tsr" ? tsrBranch(pb, sol.branches[i], i, a.result.window)
                                           : moveitBranch(pb, sol.branches[i], i, a.result.window));
    } catch (const std::exception& e) {  // a plugin's manifold that throws: this branch only
      branches.push_back({{"index", i},
                          {"exact", false},
                          {a.format == "tsr" ? "tsr_chain" : "constraints", nullptr},
                          {"why", std::string("the branch's code threw: ") + e.what()}});
    }
  }
  doc["branches"] = branches;
  const std::string text = doc.dump(2) + "\n";
  if (!a.out.empty()) {
    replaceFile(a.out, text);
    return kExitOk;
  }
  std::cout << text << std::flush;
  if (!std::cout) throw WriteFailed("standard output: cannot write the result");
  return kExitOk;
}

}  // namespace relpos::cli
