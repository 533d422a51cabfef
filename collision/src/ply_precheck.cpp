// The PLY check: the header parsed as CGAL's PLY_reader::init parses it (CGAL 5.5), then every
// element read property by property in CGAL's order, each list's length checked before CGAL would
// allocate room for it.
#include <CGAL/IO/io.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

#include "mesh_precheck.hpp"

namespace relpos::collision::detail {
namespace {

enum class Type { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

// The type a PLY name stands for, by CGAL's table; false for a name CGAL does not know (it would
// skip the property without reading it, and read the rest of the file out of step).
bool typeNamed(const std::string& name, Type* t) {
  static const std::pair<const char*, Type> kNames[] = {
      {"char", Type::kInt8},      {"int8", Type::kInt8},       {"uchar", Type::kUInt8},
      {"uint8", Type::kUInt8},    {"short", Type::kInt16},     {"int16", Type::kInt16},
      {"ushort", Type::kUInt16},  {"uint16", Type::kUInt16},   {"int", Type::kInt32},
      {"int32", Type::kInt32},    {"uint", Type::kUInt32},     {"uint32", Type::kUInt32},
      {"float", Type::kFloat32},  {"float32", Type::kFloat32}, {"double", Type::kFloat64},
      {"float64", Type::kFloat64}};
  for (const auto& [n, type] : kNames)
    if (name == n) return *t = type, true;
  return false;
}

std::size_t sizeOf(Type t) {
  switch (t) {
    case Type::kInt8:
    case Type::kUInt8:
      return 1;
    case Type::kInt16:
    case Type::kUInt16:
      return 2;
    case Type::kInt32:
    case Type::kUInt32:
    case Type::kFloat32:
      return 4;
    case Type::kFloat64:
      return 8;
  }
  return 8;
}

struct Property {
  std::string name;
  bool list = false;
  Type length = Type::kUInt8;  // a list's length type
  Type type = Type::kFloat32;  // the value's (a list's items')
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
};

enum class Format { kAscii, kLittleEndian, kBigEndian };

// The file's body, read value by value as PLY_read_number::read reads it.
class Body {
 public:
  Body(std::istream& in, const std::string& text, Format format)
      : in_(in), text_(text), format_(format), at_(offset()) {}

  // What is left of the file, in bytes.
  std::size_t remaining() const {
    return text_.size() - (format_ == Format::kAscii ? offset() : at_);
  }

  // The next value; false when there is none to read (CGAL's stream would fail).
  bool read(Type t, double* value) {
    return format_ == Format::kAscii ? readAscii(t, value) : readBinary(t, value);
  }

 private:
  // Reads a Read and keeps it as a Stored, as CGAL does.
  template <typename Read, typename Stored = Read>
  bool extract(double* value) {
    Read x;
    if (!(in_ >> x)) return false;
    *value = static_cast<Stored>(x);
    return true;
  }

  bool readAscii(Type t, double* value) {
    switch (t) {  // CGAL reads the one-byte types through a short, the reals through iformat
      case Type::kInt8:
        return extract<short, signed char>(value);
      case Type::kUInt8:
        return extract<unsigned short, unsigned char>(value);
      case Type::kInt16:
        return extract<std::int16_t>(value);
      case Type::kUInt16:
        return extract<std::uint16_t>(value);
      case Type::kInt32:
        return extract<std::int32_t>(value);
      case Type::kUInt32:
        return extract<std::uint32_t>(value);
      case Type::kFloat32: {
        float f;
        if (!(in_ >> CGAL::IO::iformat(f))) return false;
        return *value = f, true;
      }
      case Type::kFloat64:
        return static_cast<bool>(in_ >> CGAL::IO::iformat(*value));
    }
    return false;
  }

  template <typename T>
  double decode(const char* bytes) {
    char b[sizeof(T)];
    std::memcpy(b, bytes, sizeof(T));
    if (format_ == Format::kBigEndian) std::reverse(b, b + sizeof(T));
    T x;
    std::memcpy(&x, b, sizeof(T));
    return static_cast<double>(x);
  }

  bool readBinary(Type t, double* value) {
    // A short read would leave CGAL's value half garbage: there must be all of it.
    const std::size_t n = sizeOf(t);
    if (text_.size() - at_ < n) return false;
    const char* p = text_.data() + at_;
    at_ += n;
    switch (t) {
      case Type::kInt8:
        *value = decode<std::int8_t>(p);
        break;
      case Type::kUInt8:
        *value = decode<std::uint8_t>(p);
        break;
      case Type::kInt16:
        *value = decode<std::int16_t>(p);
        break;
      case Type::kUInt16:
        *value = decode<std::uint16_t>(p);
        break;
      case Type::kInt32:
        *value = decode<std::int32_t>(p);
        break;
      case Type::kUInt32:
        *value = decode<std::uint32_t>(p);
        break;
      case Type::kFloat32:
        *value = decode<float>(p);
        break;
      case Type::kFloat64:
        *value = decode<double>(p);
        break;
    }
    return true;
  }

  // Where the text stream is (at the end once it has failed).
  std::size_t offset() const {
    const auto at = in_.tellg();
    return at < 0 ? text_.size() : static_cast<std::size_t>(at);
  }

  std::istream& in_;
  const std::string& text_;
  Format format_;
  std::size_t at_;  // binary: the next byte
};

// The header's format and elements. False when it is not usable, with what is wrong in `error`
// ("" for a header CGAL refuses by itself).
bool readHeader(std::istream& in, Format* format, std::vector<Element>* elements,
                std::string* error) {
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    if (number == 1) {
      std::string signature;
      if (!(words >> signature) || signature != "ply") return false;
      continue;
    }
    if (number == 2) {
      std::string tag, name, version;
      if (!(words >> tag >> name >> version)) return false;
      if (name == "ascii")
        *format = Format::kAscii;
      else if (name == "binary_little_endian")
        *format = Format::kLittleEndian;
      else if (name == "binary_big_endian")
        *format = Format::kBigEndian;
      else
        return false;
      continue;
    }
    std::string keyword;
    if (!(words >> keyword)) return false;
    if (keyword == "end_header") return true;
    if (keyword == "element") {
      Element e;
      if (!(words >> e.name >> e.count)) return false;
      elements->push_back(e);
    } else if (keyword == "property") {
      Property p;
      std::string type;
      if (!(words >> type >> p.name)) return false;
      // (CGAL adds the property to the last element, there or not.)
      if (elements->empty())
        return *error = "PLY property '" + p.name + "' before any element", false;
      if (type == "list") {
        const std::string length = p.name;
        if (!(words >> type >> p.name)) return false;
        p.list = true;
        if (!typeNamed(length, &p.length) || p.length == Type::kFloat32 ||
            p.length == Type::kFloat64)
          return *error = "unsupported PLY list length type '" + length + "'", false;
      }
      if (!typeNamed(type, &p.type))
        return *error = "unsupported PLY property type '" + type + "'", false;
      elements->back().properties.push_back(p);
    }
  }
  return *error = "PLY header without end_header", false;
}

}  // namespace

std::string precheckPly(const std::string& text) {
  TextStream in(text);
  Format format = Format::kAscii;
  std::vector<Element> elements;
  std::string error;
  if (!readHeader(in, &format, &elements, &error)) return error;
  Body body(in, text, format);
  for (const Element& e : elements) {
    // CGAL goes through every item even when there is nothing to read (a vertex each time).
    if (e.count > 0 && e.properties.empty())
      return "PLY element '" + e.name + "' has " + std::to_string(e.count) +
             " items and no properties";
    for (std::size_t i = 0; i < e.count; ++i)
      for (const Property& p : e.properties) {
        const std::string where =
            "PLY element '" + e.name + "' item " + std::to_string(i) + " property '" + p.name + "'";
        double value = 0;
        if (!body.read(p.list ? p.length : p.type, &value))
          return where + ": missing or bad value (the header counts " + std::to_string(e.count) +
                 " items)";
        if (!p.list) continue;
        // The length is checked against the rest of the file before CGAL sizes the list: each
        // item takes sizeOf bytes, or a digit and a blank.
        const std::size_t room = format == Format::kAscii ? (body.remaining() + 1) / 2
                                                          : body.remaining() / sizeOf(p.type);
        if (value < 0 || value > static_cast<double>(room))
          return where + ": a list of " + std::to_string(static_cast<long long>(value)) +
                 " values, more than the rest of the file holds";
        for (auto k = static_cast<std::size_t>(value); k > 0; --k)
          if (!body.read(p.type, &value)) return where + ": missing or bad value in the list";
      }
  }
  return "";
}

}  // namespace relpos::collision::detail
