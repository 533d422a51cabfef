// familyOfSignature (encoding.hpp): the inverse of PoseFamily's and LineFamily's signatureOf,
// "pose/P;kind(fixed,mobile,line,value);…" and "line/P;kind(fixed,value);…", with the kinds
// spelled by toString. Any other text, or equations that make no family, give nullptr.
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "relpos/complete/encoding.hpp"

namespace relpos::complete {
namespace {

// "name(a,b,…)" with `count` integers; false on anything else.
bool splitItem(const std::string& item, std::string* name, int* values, int count) {
  const std::size_t open = item.find('(');
  if (open == std::string::npos || item.empty() || item.back() != ')') return false;
  *name = item.substr(0, open);
  std::istringstream in(item.substr(open + 1, item.size() - open - 2));
  for (int i = 0; i < count; ++i) {
    if (i > 0 && in.get() != ',') return false;
    if (!(in >> values[i])) return false;
  }
  return in.peek() == std::char_traits<char>::eof();
}

template <typename Kind>
bool kindNamed(const std::string& name, std::initializer_list<Kind> kinds, Kind* out) {
  for (Kind k : kinds)
    if (name == toString(k)) {
      *out = k;
      return true;
    }
  return false;
}

std::unique_ptr<Family> poseFamily(int parameters, const std::vector<std::string>& items) {
  using K = PoseEquationKind;
  std::vector<PoseEquation> eqs;
  for (const std::string& item : items) {
    std::string name;
    int v[4];
    PoseEquation q;
    if (!splitItem(item, &name, v, 4) ||
        !kindNamed(name,
                   {K::kChart, K::kStudy, K::kPointPoint, K::kPointPlane, K::kPlanePoint,
                    K::kPointLine, K::kLinePoint, K::kDirection, K::kNorm},
                   &q.kind))
      return nullptr;
    q.fixed = v[0], q.mobile = v[1], q.line = v[2], q.value = v[3];
    eqs.push_back(q);
  }
  return std::make_unique<PoseFamily>(std::move(eqs), parameters);
}

std::unique_ptr<Family> lineFamily(int parameters, const std::vector<std::string>& items) {
  using K = LineEquationKind;
  std::vector<LineEquation> eqs;
  for (const std::string& item : items) {
    std::string name;
    int v[2];
    LineEquation q;
    if (!splitItem(item, &name, v, 2) ||
        !kindNamed(name, {K::kUnit, K::kFoot, K::kPointDistance, K::kDirection, K::kPlaneOffset},
                   &q.kind))
      return nullptr;
    q.fixed = v[0], q.value = v[1];
    eqs.push_back(q);
  }
  return std::make_unique<LineFamily>(std::move(eqs), parameters);
}

}  // namespace

std::unique_ptr<Family> familyOfSignature(const std::string& signature) {
  std::vector<std::string> items;
  std::istringstream in(signature);
  for (std::string item; std::getline(in, item, ';');) items.push_back(item);
  if (items.empty()) return nullptr;
  const std::string head = items.front();
  items.erase(items.begin());
  const std::size_t slash = head.find('/');
  if (slash == std::string::npos) return nullptr;
  int parameters = -1;
  char extra = 0;
  if (std::sscanf(head.c_str() + slash + 1, "%d%c", &parameters, &extra) != 1 || parameters < 0)
    return nullptr;
  const std::string kind = head.substr(0, slash);
  try {
    std::unique_ptr<Family> f = kind == "pose"   ? poseFamily(parameters, items)
                                : kind == "line" ? lineFamily(parameters, items)
                                                 : nullptr;
    // The round trip decides: a text that parses but is spelled otherwise is not a signature.
    if (f && f->signature() != signature) return nullptr;
    return f;
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

}  // namespace relpos::complete
