// relpos._relpos: the compiled half of the Python package (python/relpos/__init__.py is the
// other). It parses a spec (a file, or the JSON text the package made of a dict), solves it,
// evaluates the report (nearest poses, samples, collisions) and keeps all three alive so that
// the branches can be asked for poses afterwards. What users call is in python/relpos/; the
// names here are private (a leading underscore on the module).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "relpos/builtins/builtins.hpp"
#include "relpos/collision/scene.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/result_writer.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/loader.hpp"
#include "relpos/plugins/search.hpp"
#include "relpos/report/evaluate.hpp"
#include "relpos/report/tsr.hpp"
#include "relpos/viewer/page.hpp"

namespace py = pybind11;

namespace {

using relpos::Isometry3d;
using Matrix4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

// The registry every solve uses: the built-ins and the plugins loaded so far. A loaded plugin
// cannot be added to a frozen registry, so loading one makes a new registry (solutions already
// made keep the libraries they need: Solution::libraries).
class Plugins {
 public:
  std::shared_ptr<const relpos::Registry> registry() {
    if (!registry_) registry_ = build(paths_, nullptr);
    return registry_;
  }
  // Loads `path` (after the ones loaded before); a RuntimeError naming it on failure, and then
  // nothing changes.
  // The folder of the package, whose plugin folders a name is looked for in.
  void setProgramDir(const std::string& dir) { folders_ = relpos::plugins::pluginFoldersFor(dir); }
  void load(const std::string& name) {
    const std::string path = relpos::plugins::findPlugin(name, folders_);
    for (const std::string& p : paths_)
      if (p == path) return;
    std::vector<std::string> paths = paths_;
    paths.push_back(path);
    std::string error;
    auto reg = build(paths, &error);
    if (!reg) throw std::runtime_error(error);
    paths_ = std::move(paths);
    registry_ = std::move(reg);
  }
  const std::vector<std::string>& paths() const { return paths_; }

 private:
  static std::shared_ptr<const relpos::Registry> build(const std::vector<std::string>& paths,
                                                       std::string* error) {
    auto reg = std::make_shared<relpos::Registry>();
    relpos::registerBuiltins(*reg);
    for (const std::string& p : paths) {
      std::string why;
      if (!relpos::plugins::loadPlugin(p, *reg, &why)) {
        if (error) *error = why;
        return nullptr;
      }
    }
    reg->freeze();
    return reg;
  }
  std::vector<std::string> paths_, folders_;
  std::shared_ptr<const relpos::Registry> registry_;
};

Plugins& plugins() {
  static Plugins p;
  return p;
}

py::list diagnostics(const std::vector<relpos::Diagnostic>& ds) {
  py::list out;
  for (const auto& d : ds) out.append(py::make_tuple(d.path, d.message));
  return out;
}

Matrix4 toMatrix(const Isometry3d& X) { return Matrix4(X.matrix()); }

// A 4x4 homogeneous matrix whose upper left 3x3 is a rotation (to 1e-6), else ValueError.
Isometry3d fromMatrix(const Matrix4& M) {
  if (!M.allFinite()) throw py::value_error("the pose holds a NaN or an infinity");
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  if ((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 ||
      R.determinant() < 0.0 || M.row(3).cwiseAbs().sum() - 1.0 > 1e-12 || M(3, 3) != 1.0)
    throw py::value_error(
        "the pose must be a 4x4 homogeneous matrix: a rotation (orthonormal, determinant 1) and "
        "a translation, last row 0 0 0 1");
  Isometry3d X = Isometry3d::Identity();
  // Re-orthonormalised: a rotation read from a file with 6 digits is not one to 1e-16.
  X.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  X.translation() = M.topRightCorner<3, 1>();
  return X;
}

struct SolveOptions {
  int samples = 0;
  double window = 1.0;
  std::uint64_t seed = 0;
  bool collision = false;
  double clearance = 0.0;
  int collision_samples = 64;
  bool degrees = false;  // the document's angles in degrees (angles="deg")
};

// A solved spec: the problem, the solution, its report and the result document, kept together
// (a branch's manifold may be a plugin's: the solution keeps its library loaded).
class Solved {
 public:
  std::shared_ptr<const relpos::Registry> registry;
  relpos::Problem problem;
  relpos::Solution solution;
  relpos::Report report;
  std::string json;
  std::string spec_dir;  // meshes' relative paths are relative to it

  int branchCount() const {
    // A report made after a plugin threw has no branch (unhandledAfterThrow): none to run.
    return report.branches.size() == solution.branches.size()
               ? static_cast<int>(solution.branches.size())
               : 0;
  }
  const relpos::Branch& branch(int i) const {
    if (i < 0 || i >= branchCount()) throw py::index_error("no such branch");
    return solution.branches[static_cast<std::size_t>(i)];
  }
};

// The result of parsing: the solved spec, or the errors (and the warnings either way).
py::tuple solveParsed(relpos::ParseResult r, const std::string& spec_dir,
                      std::shared_ptr<const relpos::Registry> reg, const SolveOptions& o) {
  py::list warnings = diagnostics(r.warnings);
  if (!r.problem) return py::make_tuple(py::none(), diagnostics(r.errors), warnings);
  auto s = std::make_shared<Solved>();
  s->registry = std::move(reg);
  s->problem = std::move(*r.problem);
  s->spec_dir = spec_dir;
  relpos::ReportOptions ro;
  ro.samples = o.samples;
  ro.window = o.window;
  ro.seed = o.seed;
  ro.clearance = o.clearance;
  ro.collision_samples = o.collision_samples;
  std::vector<relpos::Diagnostic> scene_errors, scene_warnings;
  {
    py::gil_scoped_release unlocked;
    relpos::Workspace ws;
    relpos::solve(s->problem, *s->registry, relpos::SolverOptions(), ws, s->solution);
    if (o.collision) {
      relpos::collision::MeshCache cache;
      auto scene = relpos::collision::buildScene(s->problem, spec_dir, cache, &scene_errors,
                                                 &scene_warnings);
      if (scene) relpos::evaluate(s->problem, s->solution, ro, s->report, scene.get());
    } else {
      relpos::evaluate(s->problem, s->solution, ro, s->report);
    }
    relpos::ResultFormat format = relpos::kResultDocument;
    format.degrees = o.degrees;
    if (scene_errors.empty()) relpos::writeReport(s->report, format, s->json);
  }
  for (const auto& w : scene_warnings) warnings.append(py::make_tuple(w.path, w.message));
  if (!scene_errors.empty()) return py::make_tuple(py::none(), diagnostics(scene_errors), warnings);
  return py::make_tuple(s, py::list(), warnings);
}

// A spec's entries, joined to `dir`: a bare name that names no file there is looked for by name
// beside the package.
void loadSpecPlugins(const std::vector<std::string>& paths, const std::string& dir) {
  for (const std::string& p : paths) {
    const std::string bare = relpos::plugins::bareEntry(p, dir);
    plugins().load(!bare.empty() && !std::filesystem::exists(p) ? bare : p);
  }
}

py::tuple solveFile(const std::string& file, const SolveOptions& o) {
  if (!std::filesystem::is_regular_file(file))
    throw py::value_error(file + ": no such file (a spec is a path to a .json file or a dict)");
  const std::string dir = std::filesystem::path(file).parent_path().string();
  loadSpecPlugins(relpos::specPluginPaths(file), dir);
  auto reg = plugins().registry();
  return solveParsed(relpos::parseSpecFile(file, *reg), dir, reg, o);
}

py::tuple solveText(const std::string& text, const std::string& base_dir, const SolveOptions& o) {
  loadSpecPlugins(relpos::specPluginPathsInText(text, base_dir), base_dir);
  auto reg = plugins().registry();
  return solveParsed(relpos::parseSpec(text, *reg), base_dir, reg, o);
}

// A branch of a solved spec; keeps the spec alive.
struct BranchRef {
  std::shared_ptr<const Solved> solved;
  int index = 0;
  const relpos::Branch& branch() const { return solved->branch(index); }
  const relpos::BranchReport& report() const {
    return solved->report.branches[static_cast<std::size_t>(index)];
  }
};

relpos::Params paramsOf(const BranchRef& b, const std::vector<double>& values) {
  const relpos::Manifold& m = *b.branch().manifold;
  const int n = m.dof();
  if (static_cast<int>(values.size()) != n)
    throw py::value_error("the branch has " + std::to_string(n) + " parameters, not " +
                          std::to_string(values.size()));
  relpos::Params t{};
  for (int i = 0; i < n; ++i) {
    const relpos::Parameter p = m.parameter(i);
    const double v = values[static_cast<std::size_t>(i)];
    const std::string name = p.name;
    if (!std::isfinite(v)) throw py::value_error(name + ": not a finite number");
    // Outside its bounds a parameter gives a pose that need not satisfy the constraints.
    const double slack = 1e-12 * (1.0 + std::abs(v));
    if (!p.periodic && (v < p.min - slack || v > p.max + slack))
      throw py::value_error(name + " = " + std::to_string(v) + " is outside its bounds [" +
                            std::to_string(p.min) + ", " + std::to_string(p.max) + "]");
    t[i] = v;
  }
  return t;
}

py::list paramList(const relpos::Params& t, int n) {
  py::list out;
  for (int i = 0; i < n; ++i) out.append(t[i]);
  return out;
}

Matrix4 branchPose(const BranchRef& b, const std::vector<double>& values) {
  const relpos::Params t = paramsOf(b, values);
  return toMatrix(b.branch().manifold->pose(t));
}

py::dict branchNearest(const BranchRef& b, const Matrix4& M) {
  const Isometry3d X = fromMatrix(M);
  relpos::NearestPose n;
  {
    py::gil_scoped_release unlocked;
    n = relpos::nearestOnBranch(b.branch(), X);
  }
  py::dict d;
  d["parameters"] = paramList(n.parameters, b.branch().manifold->dof());
  d["pose"] = toMatrix(n.pose);
  d["distance"] = n.distance;
  d["global"] = n.global;
  return d;
}

// n poses drawn as the result's samples are (docs/spec.md §2.7): uniformly within the bounds,
// an unbounded length within ±window of the nearest pose's; deterministic for a seed.
py::tuple branchSample(const BranchRef& b, int n, double window, std::uint64_t seed) {
  if (n < 0) throw py::value_error("the number of samples must be >= 0");
  if (!(window >= 0.0) || !std::isfinite(window)) throw py::value_error("window must be >= 0");
  const relpos::Manifold& m = *b.branch().manifold;
  const int dof = m.dof();
  py::array_t<double> params({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(dof)});
  py::array_t<double> poses({static_cast<py::ssize_t>(n), py::ssize_t{4}, py::ssize_t{4}});
  auto P = params.mutable_unchecked<2>();
  auto X = poses.mutable_unchecked<3>();
  std::mt19937_64 rng(seed);
  const relpos::Params centre = b.report().nearest.parameters;
  for (int k = 0; k < n; ++k) {
    const relpos::Params t = relpos::sampleParameters(m, centre, window, rng);
    const Matrix4 pose = toMatrix(m.pose(t));
    for (int i = 0; i < dof; ++i) P(k, i) = t[i];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) X(k, r, c) = pose(r, c);
  }
  return py::make_tuple(params, poses);
}

py::list branchParameters(const BranchRef& b) {
  const relpos::Manifold& m = *b.branch().manifold;
  py::list out;
  for (int i = 0; i < m.dof(); ++i) {
    const relpos::Parameter p = m.parameter(i);
    py::dict d;
    d["name"] = p.name;
    d["kind"] = relpos::toString(p.kind);
    d["min"] = p.min;
    d["max"] = p.max;
    d["periodic"] = p.periodic;
    out.append(d);
  }
  return out;
}

// The branch as a TSR chain (docs/spec.md §3.11): exact, why (when not), window (when bounded
// by it) and the chain's links as numpy arrays.
py::dict branchTsr(const BranchRef& b, double window) {
  if (!(window > 0.0) || !std::isfinite(window)) throw py::value_error("window must be > 0");
  const relpos::TsrExport e =
      relpos::tsrChainOf(b.solved->problem, b.branch(), b.report().nearest.parameters, window);
  py::dict d;
  d["exact"] = e.exact;
  d["why"] = e.exact ? py::object(py::none()) : py::object(py::str(e.why));
  if (e.windowed) d["window"] = window;
  if (!e.exact) {
    d["tsr_chain"] = py::none();
    return d;
  }
  py::list chain;
  for (const relpos::TsrLink& l : e.chain) {
    Eigen::Matrix<double, 6, 2, Eigen::RowMajor> Bw;
    for (int r = 0; r < 6; ++r) Bw(r, 0) = l.Bw[r][0], Bw(r, 1) = l.Bw[r][1];
    py::dict link;
    link["T0_w"] = toMatrix(l.T0_w);
    link["Tw_e"] = toMatrix(l.Tw_e);
    link["Bw"] = Bw;
    chain.append(link);
  }
  d["tsr_chain"] = chain;
  return d;
}

// The page `relpos view` writes (docs/spec.md §3.12), for a solved spec; ValueError when a mesh
// cannot be read.
std::string solvedPage(const Solved& s, int samples, double window, bool degrees) {
  relpos::ReportOptions ro;
  ro.samples = samples;
  ro.window = window;
  relpos::viewer::ViewOptions view;
  view.window = window;
  view.degrees = degrees;
  view.spec_dir = s.spec_dir;
  std::string html;
  std::vector<relpos::Diagnostic> errors, warnings;
  {
    py::gil_scoped_release unlocked;
    const relpos::Report report = relpos::evaluate(s.problem, s.solution, ro);
    relpos::viewer::writePage(s.problem, s.solution, report, view, &html, &errors, &warnings);
  }
  if (!errors.empty()) throw py::value_error(errors[0].path + ": " + errors[0].message);
  return html;
}

}  // namespace

PYBIND11_MODULE(_relpos, m) {
  m.doc() = "relpos's compiled core; use the relpos package, not this module";
  m.attr("__version__") = RELPOS_VERSION;
  py::class_<SolveOptions>(m, "SolveOptions")
      .def(py::init<>())
      .def_readwrite("samples", &SolveOptions::samples)
      .def_readwrite("window", &SolveOptions::window)
      .def_readwrite("seed", &SolveOptions::seed)
      .def_readwrite("collision", &SolveOptions::collision)
      .def_readwrite("clearance", &SolveOptions::clearance)
      .def_readwrite("collision_samples", &SolveOptions::collision_samples)
      .def_readwrite("degrees", &SolveOptions::degrees);
  py::class_<Solved, std::shared_ptr<Solved>>(m, "Solved")
      .def_readonly("json", &Solved::json)
      .def_property_readonly("branch_count", &Solved::branchCount)
      .def("branch",
           [](const std::shared_ptr<Solved>& s, int i) {
             s->branch(i);  // IndexError for a bad index
             return BranchRef{s, i};
           })
      .def("page", &solvedPage)
      // The problem's size (its largest coordinate; 1 when all are 0): the view's window.
      .def_property_readonly("size", [](const Solved& s) {
        const double size = s.problem.lengthScale();
        return size > 0.0 ? size : 1.0;
      });
  py::class_<BranchRef>(m, "BranchRef")
      .def_property_readonly("index", [](const BranchRef& b) { return b.index; })
      .def_property_readonly("dof", [](const BranchRef& b) { return b.branch().manifold->dof(); })
      .def_property_readonly("exact", [](const BranchRef& b) { return b.branch().exact; })
      .def_property_readonly("manifold", [](const BranchRef& b) { return b.report().manifold; })
      .def_property_readonly("parameters", &branchParameters)
      .def("pose", &branchPose)
      .def("nearest", &branchNearest)
      .def("sample", &branchSample)
      .def("tsr", &branchTsr);
  m.def("solve_file", &solveFile);
  m.def("solve_text", &solveText);
  m.def("load_plugin", [](const std::string& path) { plugins().load(path); });
  m.def("set_program_dir", [](const std::string& dir) { plugins().setProgramDir(dir); });
  m.def("loaded_plugins", []() { return plugins().paths(); });
}
