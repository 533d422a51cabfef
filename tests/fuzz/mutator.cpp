#include "mutator.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace relpos::fuzz {
namespace {
namespace fs = std::filesystem;
using Kind = JsonNode::Kind;

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void addSeed(const std::string& origin, const std::string& text, std::vector<Seed>& out) {
  const auto j = nlohmann::ordered_json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return;
  Seed s{origin, fromJson(j)};
  s.tree.erase("plugins");
  out.push_back(std::move(s));
}

// Keys a spec uses (docs/spec.md §1), for renaming a key into another meaningful one.
const std::vector<std::string> kKeys = {
    "relpos",    "name",        "units",       "length",    "angle",  "fixed",      "mobile",
    "pose",      "position",    "orientation", "rpy",       "matrix", "features",   "point",
    "line",      "plane",       "cylinder",    "direction", "normal", "radius",     "mesh",
    "obstacles", "constraints", "type",        "value",     "min",    "max",        "parallel",
    "id",        "axis",        "Point",       "",          "point ", "v\\u0061lue"};
const std::vector<std::string> kTypes = {"distance",      "angle",   "coincident", "parallel",
                                         "perpendicular", "tangent", "thread",     "symmetric",
                                         "Distance",      "",        "explodes",   "coincident "};
const std::vector<std::string> kOrientations = {"aligned", "opposed",  "either",
                                                "Aligned", "sideways", ""};
const std::vector<std::string> kFeatureKinds = {"point",  "line",   "plane", "cylinder",
                                                "sphere", "circle", "axis",  "Line"};

// Numbers at and beyond the edges of what a double holds, and spellings JSON does not allow.
const std::vector<std::string> kWeirdNumbers = {
    "1e300", "-1e300", "1.7976931348623157e308", "-1.7976931348623157e308", "1e154", "3e154",
    "-2e160", "1e200", "1e400", "-1e400", "1e-400", "5e-324", "-5e-324", "2.2250738585072014e-308",
    "1e-300", "1e-160", "1e-9", "1e-12", "1e-15", "0", "-0", "-0.0", "0e0", "1", "-1", "2", "1e6",
    "-1e6", "1e-6", "123456789012345678901234567890", "-9223372036854775809",
    "18446744073709551616", "9007199254740993", "3.141592653589793", "6.283185307179586",
    "1.5707963267948966", "180", "360", "-3.2",
    // not JSON numbers: the reader must say so, with where
    "NaN", "nan", "-NaN", "Infinity", "-Infinity", "inf", "1.", ".5", "01", "+1", "0x10", "1e",
    "--1", "1e+", "1_000", "1,5"};

// Bytes a name or key may hold: non-ASCII, invalid UTF-8, control characters (raw, which JSON
// forbids, and escaped, which JSON allows and the diagnostics must not print raw).
const std::vector<std::string> kWeirdBytes = {"\xC3\xA9",          // é
                                              "\xF0\x9F\x98\x80",  // an emoji (4 bytes)
                                              "\xE2\x80\xAE",      // right-to-left override
                                              "\xEF\xBB\xBF",      // a byte-order mark
                                              "\xFF",
                                              "\xFE",
                                              "\x80",
                                              "\xC3",
                                              "\xE2\x82",
                                              "\xC0\x80",
                                              "\xED\xA0\x80",
                                              "\xF4\x90\x80\x80",
                                              "\x01",
                                              "\x1F",
                                              "\x7F",
                                              "\t",
                                              "\r",
                                              "\n",
                                              "\x1B[31m",
                                              "\\n",
                                              "\\r",
                                              "\\t",
                                              "\\u0000",
                                              "\\u001b",
                                              "\\ud800",
                                              "\\udc00",
                                              "\\ud83d\\ude00",
                                              "\\u00e9",
                                              "\\x41",
                                              "\\",
                                              "\\u12",
                                              "\"",
                                              ": ",
                                              "; ",
                                              ".",
                                              "[0]",
                                              "%s%n"};

}  // namespace

std::vector<Seed> loadSeeds(const std::string& data_dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(data_dir)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), data_dir);
    if (*rel.begin() == "expected") continue;  // expected results, not specs
    const std::string ext = e.path().extension().string();
    if (ext == ".json" || ext == ".jsonl") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Seed> seeds;
  for (const auto& f : files) {
    const std::string origin = "data/" + fs::relative(f, data_dir).string();
    const std::string text = readFile(f);
    if (f.extension() == ".json") {
      addSeed(origin, text, seeds);
      continue;
    }
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (!line.empty()) addSeed(origin + ":" + std::to_string(n), line, seeds);
  }
  return seeds;
}

struct Mutator::Slot {
  JsonNode* node;
  JsonNode* parent;   // nullptr for the root
  std::size_t index;  // in the parent's items
};

Mutator::Mutator(std::uint64_t seed, MutationOptions options) : rng_(seed), options_(options) {}

std::size_t Mutator::below(std::size_t n) {
  return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n);
}
bool Mutator::chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
std::string Mutator::pick(const std::vector<std::string>& options) {
  return options[below(options.size())];
}

std::vector<Mutator::Slot> Mutator::slots(JsonNode& root) {
  std::vector<Slot> out;
  std::vector<Slot> stack{{&root, nullptr, 0}};
  while (!stack.empty()) {
    Slot s = stack.back();
    stack.pop_back();
    out.push_back(s);
    for (std::size_t i = 0; i < s.node->items.size(); ++i)
      stack.push_back({&s.node->items[i], s.node, i});
  }
  return out;
}

std::string Mutator::weirdNumber() {
  if (chance(0.3)) {  // an ordinary value: another problem, often still valid
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", std::uniform_real_distribution<double>(-5, 5)(rng_));
    return buf;
  }
  return pick(kWeirdNumbers);
}

std::string Mutator::weirdBytes() {
  std::string s = pick(kWeirdBytes);
  if (options_.one_line && s == "\n") s = "\x0b";
  if (chance(0.05)) {  // a long one
    std::string l;
    for (int i = 0; i < 2000; ++i) l += s.empty() ? "x" : s;
    return l;
  }
  return s;
}

std::string Mutator::deepText() {
  int depth = static_cast<int>(2 + below(60));
  const double r = std::uniform_real_distribution<double>(0, 1)(rng_);
  if (r < options_.deep_share) {
    depth = chance(0.5) ? 100000 : 300000;
  } else if (r < 0.1) {
    depth = std::vector<int>{100, 1000, 10000}[below(3)];
  }
  depth = std::min(depth, options_.max_depth);
  std::string open, close;
  switch (below(3)) {
    case 0:
      open = "[", close = "]";
      break;
    case 1:
      open = "{\"a\":", close = "}";
      break;
    default:
      open = "[{\"point\":", close = "}]";
  }
  std::string s;
  s.reserve(static_cast<std::size_t>(depth) * (open.size() + close.size()) + 2);
  for (int i = 0; i < depth; ++i) s += open;
  s += chance(0.5) ? "1" : "[]";
  if (chance(0.1)) return s;  // unclosed
  for (int i = 0; i < depth; ++i) s += close;
  return s;
}

JsonNode Mutator::randomScalar() {
  switch (below(7)) {
    case 0:
      return JsonNode::null();
    case 1:
      return JsonNode::boolean(chance(0.5));
    case 2:
      return JsonNode::number(weirdNumber());
    case 3:
      return JsonNode::string(chance(0.5) ? weirdBytes() : pick(kKeys));
    case 4: {
      JsonNode a = JsonNode::array();
      const std::size_t n = below(5);
      for (std::size_t i = 0; i < n; ++i) a.items.push_back(JsonNode::number(weirdNumber()));
      return a;
    }
    case 5: {
      JsonNode o = JsonNode::object();
      o.set(pick(kKeys), JsonNode::number(weirdNumber()));
      return o;
    }
    default:
      return JsonNode::raw(deepText());
  }
}

// A feature of any kind, with ordinary or odd numbers.
JsonNode Mutator::randomFeature() {
  auto vec = [&](bool odd) {
    JsonNode a = JsonNode::array();
    for (int i = 0; i < 3; ++i) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3g", std::uniform_real_distribution<double>(-1, 1)(rng_));
      a.items.push_back(JsonNode::number(odd && chance(0.3) ? weirdNumber() : buf));
    }
    return a;
  };
  const bool odd = chance(0.3);
  const std::string kind = chance(0.9) ? kFeatureKinds[below(4)] : pick(kFeatureKinds);
  JsonNode f = JsonNode::object();
  if (kind == "point") {
    f.set(kind, vec(odd));
    return f;
  }
  JsonNode body = JsonNode::object();
  body.set("point", vec(odd));
  body.set(kind == "plane" ? "normal" : "direction", vec(odd));
  if (kind == "cylinder" || chance(0.05))
    body.set("radius", JsonNode::number(chance(0.7) ? "0.05" : weirdNumber()));
  f.set(kind, std::move(body));
  return f;
}

bool Mutator::mutateTree(JsonNode& root, std::string& what) {
  std::vector<Slot> all = slots(root);
  auto anyWhere = [&](auto&& accept) -> Slot* {
    std::vector<Slot*> ok;
    for (Slot& s : all)
      if (accept(s)) ok.push_back(&s);
    return ok.empty() ? nullptr : ok[below(ok.size())];
  };
  auto objects = [&](const Slot& s) {
    return s.node->kind == Kind::kObject && !s.node->items.empty();
  };
  auto arrays = [&](const Slot& s) {
    return s.node->kind == Kind::kArray && !s.node->items.empty();
  };
  JsonNode* constraints = root.member("constraints");
  auto aConstraint = [&]() -> JsonNode* {
    if (!constraints || constraints->kind != Kind::kArray || constraints->items.empty())
      return nullptr;
    JsonNode* c = &constraints->items[below(constraints->items.size())];
    return c->kind == Kind::kObject ? c : nullptr;
  };
  auto featuresOf = [&](const char* side) -> JsonNode* {
    JsonNode* o = root.member(side);
    JsonNode* f = o ? o->member("features") : nullptr;
    return f && f->kind == Kind::kObject ? f : nullptr;
  };
  // The feature names of a side as a constraint names them (with ".axis" for cylinders).
  auto featureNames = [&](const char* side) {
    std::vector<std::string> names;
    if (JsonNode* f = featuresOf(side))
      for (std::size_t i = 0; i < f->keys.size(); ++i) {
        names.push_back(f->keys[i]);
        if (f->items[i].member("cylinder")) names.push_back(f->keys[i] + ".axis");
      }
    return names;
  };

  // Edits that keep a spec valid but make it another problem (vector components swapped, a
  // number moved a little or a lot, another type, feature, orientation, value, constraint,
  // pose) are picked more often than the others, so that about half the mutants reach the
  // solver; numbers moved by 1e-15 … 1e-4 of themselves make near-degenerate geometry.
  static const std::vector<std::size_t> kKeepsValid = {6,  16, 17, 18, 19, 20, 21, 22,
                                                       23, 24, 25, 26, 27, 30, 30, 30};
  switch (chance(0.5) ? kKeepsValid[below(kKeepsValid.size())] : below(31)) {
    case 30: {  // a number moved by a small or large fraction of itself
      Slot* s = anyWhere([](const Slot& x) { return x.node->kind == Kind::kNumber; });
      if (!s) return false;
      const double v = std::strtod(s->node->text.c_str(), nullptr);
      static const double kSteps[] = {1e-15, 1e-12, 1e-9, 1e-8, 1e-7, 1e-4, 0.1, 1};
      const double step = kSteps[below(8)] * (chance(0.5) ? 1 : -1);
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", v == 0 ? step : v * (1 + step));
      s->node->text = buf;
      what += "number moved to " + s->node->text;
      return true;
    }
    case 0: {  // delete a member
      Slot* s = anyWhere(objects);
      if (!s) return false;
      const std::size_t i = below(s->node->items.size());
      what += "delete member '" + s->node->keys[i] + "'";
      s->node->keys.erase(s->node->keys.begin() + static_cast<std::ptrdiff_t>(i));
      s->node->items.erase(s->node->items.begin() + static_cast<std::ptrdiff_t>(i));
      return true;
    }
    case 1: {  // duplicate a member (a duplicate key), the copy sometimes changed
      Slot* s = anyWhere(objects);
      if (!s) return false;
      const std::size_t i = below(s->node->items.size());
      const std::string key = s->node->keys[i];
      JsonNode copy = s->node->items[i];
      if (chance(0.5)) copy = randomScalar();
      what += "duplicate key '" + key + "'";
      const std::size_t at = below(s->node->items.size() + 1);
      s->node->keys.insert(s->node->keys.begin() + static_cast<std::ptrdiff_t>(at), key);
      s->node->items.insert(s->node->items.begin() + static_cast<std::ptrdiff_t>(at), copy);
      return true;
    }
    case 2: {  // swap two members' values, or two keys
      Slot* s = anyWhere([&](const Slot& x) { return objects(x) && x.node->items.size() > 1; });
      if (!s) return false;
      const std::size_t i = below(s->node->items.size()), j = below(s->node->items.size());
      if (chance(0.5)) {
        what += "swap values of '" + s->node->keys[i] + "' and '" + s->node->keys[j] + "'";
        std::swap(s->node->items[i], s->node->items[j]);
      } else {
        what += "swap keys '" + s->node->keys[i] + "' and '" + s->node->keys[j] + "'";
        std::swap(s->node->keys[i], s->node->keys[j]);
      }
      return true;
    }
    case 3: {  // rename a key
      Slot* s = anyWhere(objects);
      if (!s) return false;
      const std::size_t i = below(s->node->items.size());
      const std::string to = chance(0.7) ? pick(kKeys) : s->node->keys[i] + weirdBytes();
      what += "rename key '" + s->node->keys[i] + "' to '" + to + "'";
      s->node->keys[i] = to;
      return true;
    }
    case 4: {  // delete an element
      Slot* s = anyWhere(arrays);
      if (!s) return false;
      what += "delete an element";
      s->node->items.erase(s->node->items.begin() +
                           static_cast<std::ptrdiff_t>(below(s->node->items.size())));
      return true;
    }
    case 5: {  // duplicate an element
      Slot* s = anyWhere(arrays);
      if (!s) return false;
      what += "duplicate an element";
      const JsonNode copy = s->node->items[below(s->node->items.size())];
      s->node->items.insert(
          s->node->items.begin() + static_cast<std::ptrdiff_t>(below(s->node->items.size() + 1)),
          copy);
      return true;
    }
    case 6: {  // swap two elements
      Slot* s = anyWhere([&](const Slot& x) { return arrays(x) && x.node->items.size() > 1; });
      if (!s) return false;
      what += "swap elements";
      std::swap(s->node->items[below(s->node->items.size())],
                s->node->items[below(s->node->items.size())]);
      return true;
    }
    case 7:
    case 8: {  // change a value's type (number, string, array, object, null, bool, deep)
      Slot* s = anyWhere([](const Slot& x) { return x.parent != nullptr; });
      if (!s) return false;
      what += "change a value's type";
      *s->node = randomScalar();
      return true;
    }
    case 9: {  // a value copied over another (a feature where a number belongs)
      Slot* from = anyWhere([](const Slot&) { return true; });
      Slot* to = anyWhere([](const Slot& x) { return x.parent != nullptr; });
      if (!from || !to || from->node == to->node) return false;
      what += "copy a value over another";
      JsonNode copy = *from->node;  // before: `to` may lie inside `from`
      *to->node = std::move(copy);
      return true;
    }
    case 10:
    case 11:
    case 12: {  // a number: huge, tiny, negative, beyond range, NaN-spelled, or ordinary
      Slot* s = anyWhere([](const Slot& x) { return x.node->kind == Kind::kNumber; });
      if (!s) return false;
      s->node->text = weirdNumber();
      what += "number " + s->node->text;
      return true;
    }
    case 13: {  // a whole vector: zero, huge or tiny components, wrong length
      Slot* s = anyWhere([](const Slot& x) {
        return x.node->kind == Kind::kArray &&
               (x.node->items.size() == 3 || x.node->items.size() == 4);
      });
      if (!s) return false;
      static const std::vector<std::vector<std::string>> vectors = {{"0", "0", "0"},
                                                                    {"0", "0", "0", "0"},
                                                                    {"1e300", "1e300", "0"},
                                                                    {"1e200", "0", "1"},
                                                                    {"2e154", "2e154", "2e154"},
                                                                    {"1e-300", "0", "0"},
                                                                    {"1e-300", "1e-300", "1e-300"},
                                                                    {"5e-324", "0", "0"},
                                                                    {"1e160", "1", "0", "0"},
                                                                    {"0", "0", "1e-200", "0"},
                                                                    {"1", "1e-17", "0"},
                                                                    {"1", "2"},
                                                                    {"1", "2", "3", "4", "5"},
                                                                    {"-0", "-0", "-1"},
                                                                    {"1e308", "1e308", "1e308"}};
      const auto& v = vectors[below(vectors.size())];
      s->node->items.clear();
      std::string text;
      for (const auto& x : v) s->node->items.push_back(JsonNode::number(x)), text += x + " ";
      what += "vector [" + text + "]";
      return true;
    }
    case 14:
    case 15: {  // a string (names) or a key gets odd bytes
      Slot* s = anyWhere([](const Slot& x) {
        return x.node->kind == Kind::kString ||
               (x.node->kind == Kind::kObject && !x.node->keys.empty());
      });
      if (!s) return false;
      std::string& target = s->node->kind == Kind::kString
                                ? s->node->text
                                : s->node->keys[below(s->node->keys.size())];
      const std::string bytes = weirdBytes();
      const std::size_t at = below(target.size() + 1);
      if (chance(0.3)) target.clear();
      target.insert(std::min(at, target.size()), bytes);
      what += "odd bytes in a name or key";
      return true;
    }
    case 16: {  // constraint type
      JsonNode* c = aConstraint();
      if (!c) return false;
      const std::string t = chance(0.8) ? kTypes[below(6)] : pick(kTypes);
      c->set("type", JsonNode::string(t));
      what += "type '" + t + "'";
      return true;
    }
    case 17: {  // a feature of another kind (or an unknown one)
      const char* side = chance(0.5) ? "fixed" : "mobile";
      JsonNode* f = featuresOf(side);
      if (!f || f->items.empty()) return false;
      const std::size_t i = below(f->items.size());
      f->items[i] = randomFeature();
      what += std::string("feature ") + side + "." + f->keys[i] + " of another kind";
      return true;
    }
    case 18: {  // another orientation
      JsonNode* c = aConstraint();
      if (!c) return false;
      const std::string o = chance(0.85) ? kOrientations[below(3)] : pick(kOrientations);
      c->set("orientation", JsonNode::string(o));
      what += "orientation '" + o + "'";
      return true;
    }
    case 19: {  // fixed and mobile names swapped in a constraint
      JsonNode* c = aConstraint();
      JsonNode* f = c ? c->member("fixed") : nullptr;
      JsonNode* m = c ? c->member("mobile") : nullptr;
      if (!f || !m) return false;
      std::swap(*f, *m);
      what += "swap a constraint's fixed and mobile";
      return true;
    }
    case 20:
    case 21: {  // a constraint on another feature of the same side (often still valid)
      JsonNode* c = aConstraint();
      if (!c) return false;
      const char* side = chance(0.5) ? "fixed" : "mobile";
      const std::vector<std::string> names = featureNames(side);
      const std::string to =
          names.empty() || chance(0.1) ? std::string("nonexistent") : names[below(names.size())];
      c->set(side, JsonNode::string(to));
      what += std::string("retarget ") + side + " to '" + to + "'";
      return true;
    }
    case 22: {  // value, range, or both
      JsonNode* c = aConstraint();
      if (!c) return false;
      auto value = [&] {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.4g",
                      std::uniform_real_distribution<double>(-0.5, 3)(rng_));
        return chance(0.8) ? std::string(buf) : weirdNumber();
      };
      switch (below(4)) {
        case 0:
          c->erase("min"), c->erase("max");
          c->set("value", JsonNode::number(value()));
          break;
        case 1:
          c->erase("value");
          c->set("min", JsonNode::number(value()));
          if (chance(0.6)) c->set("max", JsonNode::number(value()));
          break;
        case 2:
          c->erase("value");
          c->set("max", JsonNode::number(value()));
          break;
        default:
          c->set("value", JsonNode::number(value()));
          c->set("min", JsonNode::number(value()));
      }
      what += "value or range";
      return true;
    }
    case 23: {  // the parallel flag
      JsonNode* c = aConstraint();
      if (!c) return false;
      c->set("parallel", chance(0.8) ? JsonNode::boolean(chance(0.5)) : randomScalar());
      what += "parallel flag";
      return true;
    }
    case 24: {  // another constraint: a copy, or a random one between existing features
      if (!constraints || constraints->kind != Kind::kArray) return false;
      const auto f = featureNames("fixed"), m = featureNames("mobile");
      if (chance(0.4) && !constraints->items.empty()) {
        constraints->items.push_back(constraints->items[below(constraints->items.size())]);
        what += "a constraint repeated";
        return true;
      }
      if (f.empty() || m.empty()) return false;
      JsonNode c = JsonNode::object();
      c.set("type", JsonNode::string(kTypes[below(6)]));
      c.set("fixed", JsonNode::string(f[below(f.size())]));
      c.set("mobile", JsonNode::string(m[below(m.size())]));
      if (chance(0.5)) c.set("value", JsonNode::number(chance(0.5) ? "0" : "0.1"));
      if (chance(0.3)) c.set("orientation", JsonNode::string(kOrientations[below(3)]));
      constraints->items.push_back(std::move(c));
      what += "a constraint added";
      return true;
    }
    case 25: {  // units and version
      switch (below(3)) {
        case 0: {
          JsonNode u = JsonNode::object();
          u.set("angle", JsonNode::string(pick({"deg", "rad", "grad", "", "DEG"})));
          root.set("units", std::move(u));
          break;
        }
        case 1:
          root.set("relpos", JsonNode::number(pick({"2", "0", "1.0", "1e0", "-1"})));
          break;
        default:
          root.set("relpos", JsonNode::string("1"));
      }
      what += "units or version";
      return true;
    }
    case 26: {  // a pose: another orientation form, odd quaternion, matrix, far position
      const char* side = chance(0.5) ? "fixed" : "mobile";
      JsonNode* o = root.member(side);
      if (!o || o->kind != Kind::kObject) return false;
      JsonNode pose = JsonNode::object();
      auto nums = [&](std::vector<std::string> v) {
        JsonNode a = JsonNode::array();
        for (auto& x : v) a.items.push_back(JsonNode::number(x));
        return a;
      };
      switch (below(6)) {
        case 0:
          pose.set("orientation", nums({"0.1", "-0.7", "0.3", "0.2"}));
          break;
        case 1:
          pose.set("rpy", nums({"0.3", "1.5707963267948966", "-2"}));
          break;
        case 2: {  // a rigid matrix, or a row made non-rigid
          JsonNode m = JsonNode::array();
          m.items.push_back(nums({"0", "-1", "0", "1"}));
          m.items.push_back(nums({"1", "0", "0", "2"}));
          m.items.push_back(nums({"0", "0", chance(0.5) ? "1" : "2", "3"}));
          m.items.push_back(nums({"0", "0", "0", "1"}));
          pose.set("matrix", std::move(m));
          break;
        }
        case 3:
          pose.set("position", nums({"1e6", "-1e6", "3"}));
          pose.set("orientation", nums({"0", "0", "1e-300", "0"}));
          break;
        case 4:
          pose.set("orientation", nums({"0", "0", "0", "1"}));
          pose.set("rpy", nums({"0", "0", "1"}));  // both forms at once
          break;
        default:
          pose.set("position", nums({weirdNumber(), "0", "0"}));
      }
      o->set("pose", std::move(pose));
      what += std::string("pose of ") + side;
      return true;
    }
    case 27: {  // fixed and mobile objects swapped
      JsonNode* f = root.member("fixed");
      JsonNode* m = root.member("mobile");
      if (!f || !m) return false;
      std::swap(*f, *m);
      what += "swap the fixed and mobile objects";
      return true;
    }
    case 28: {  // deep nesting in place of a value
      Slot* s = anyWhere([](const Slot& x) { return x.parent != nullptr; });
      if (!s) return false;
      *s->node = JsonNode::raw(deepText());
      what += "deep nesting";
      return true;
    }
    default: {  // a feature duplicated under its own name, or named like a cylinder's axis
      const char* side = chance(0.5) ? "fixed" : "mobile";
      JsonNode* f = featuresOf(side);
      if (!f || f->items.empty()) return false;
      const std::size_t i = below(f->items.size());
      const std::string name = chance(0.7) ? f->keys[i] : f->keys[i] + ".axis";
      f->keys.push_back(name);
      f->items.push_back(chance(0.5) ? f->items[i] : randomFeature());
      what += std::string("feature '") + name + "' again on " + side;
      return true;
    }
  }
}

void Mutator::mutateText(std::string& text, std::string& what) {
  if (text.empty()) return;
  const std::size_t at = below(text.size());
  switch (below(4)) {
    case 0:
      text.resize(at);
      what += "truncated at " + std::to_string(at);
      break;
    case 1:
      text.insert(at, weirdBytes());
      what += "bytes inserted at " + std::to_string(at);
      break;
    case 2:
      text.erase(at, 1 + below(3));
      what += "bytes deleted at " + std::to_string(at);
      break;
    default:
      text[at] = static_cast<char>(rng_() & 0xFF);
      what += "a byte replaced at " + std::to_string(at);
  }
}

std::string Mutator::mutate(const JsonNode& seed, const std::string& name, std::string* what) {
  JsonNode tree = seed;
  if (!name.empty()) tree.set("name", JsonNode::string(escapedBody(name)));
  std::string log;
  auto note = [&log](const std::string& edit) { log += (log.empty() ? "" : "; ") + edit; };
  // 1 to 4 edits, fewer more often; a failed one (nothing of its kind here) is retried.
  const int edits = 1 + static_cast<int>(below(4) * below(4) / 3);
  for (int e = 0, tries = 0; e < edits && tries < 20; ++tries) {
    std::string edit;
    if (!mutateTree(tree, edit)) continue;
    note(edit);
    ++e;
  }
  std::string text = serialize(tree, options_.one_line ? 0 : (chance(0.5) ? 2 : 0));
  if (chance(0.12)) {
    std::string edit;
    mutateText(text, edit);
    note(edit);
  }
  if (options_.one_line) {
    std::replace(text.begin(), text.end(), '\n', '\x0b');
    // A blank line is skipped by batch (no result line): keep every line a spec.
    if (text.find_first_not_of(" \t\r") == std::string::npos) text += "{";
  }
  if (what) *what = log;
  return text;
}

}  // namespace relpos::fuzz
