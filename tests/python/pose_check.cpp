// pose_check SPEC: reads poses from standard input (16 numbers a line: a 4x4 matrix, row-major)
// and prints, a line each, the largest violation of the spec's input constraints at that pose
// and the index of the constraint. The tests' evaluator (support/evaluator.hpp, written from
// docs/spec.md alone) for the Python tests, which must not judge relpos with relpos's own code.
// Exit 2 when the spec cannot be read or a line is not 16 numbers.
#include <iostream>
#include <sstream>
#include <string>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: pose_check SPEC < poses\n";
    return 2;
  }
  const relpos::ParseResult r = relpos::parseSpecFile(argv[1], relpos::builtinRegistry());
  if (!r.problem) {
    for (const auto& e : r.errors) std::cerr << relpos::formatDiagnostic(argv[1], e) << "\n";
    return 2;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream in(line);
    Eigen::Matrix4d M;
    for (int i = 0; i < 16; ++i)
      if (!(in >> M(i / 4, i % 4))) {
        std::cerr << "pose_check: a line is not 16 numbers: " << line << "\n";
        return 2;
      }
    relpos::Isometry3d X = relpos::Isometry3d::Identity();
    X.linear() = M.topLeftCorner<3, 3>();
    X.translation() = M.topRightCorner<3, 1>();
    int which = -1;
    const double v = relpos::test::worstViolation(*r.problem, X, &which);
    std::cout << v << " " << which << "\n";
  }
  return 0;
}
