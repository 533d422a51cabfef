// The OFF check: the file read line by line as CGAL's File_scanner_OFF reads it (CGAL 5.5), each
// number CGAL will convert to a count, an index or a colour checked first.
#include <CGAL/IO/io.h>

#include <climits>
#include <cmath>
#include <sstream>
#include <vector>

#include "mesh_precheck.hpp"

namespace relpos::collision::detail {
namespace {

// More vertices and faces than this and CGAL's header arithmetic overflows an int; no mesh a
// collision check can use comes near it.
constexpr double kMaxElements = 5e8;

// skip_until_EOL: the rest of the line, its '\n' included.
void skipLine(std::istream& in) {
  char c;
  while (in.get(c) && c != '\n') {
  }
}

// skip_comment_OFF: blanks and comment lines up to the next item. False at the end of the file.
bool skipComments(std::istream& in) {
  char c;
  while ((in >> c) && c == '#') skipLine(in);
  if (!in) return false;
  in.putback(c);
  return true;
}

// The numbers of the next line, its comment dropped, read as CGAL reads them.
bool nextLine(std::istream& in, std::vector<double>* entries) {
  if (!skipComments(in)) return false;
  std::string line;
  std::getline(in, line);
  const std::size_t comment = line.find('#');
  if (comment != std::string::npos) line.resize(comment);
  std::istringstream numbers(line);
  entries->clear();
  double d;
  while (numbers >> CGAL::IO::iformat(d)) entries->push_back(d);
  return true;
}

bool isIndex(double x, double below) { return x >= 0 && x < below && std::floor(x) == x; }

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// A colour of 3 or 4 components that CGAL's scan_color converts to bytes without overflow: whole
// numbers 0…255, or fractions 0…1 (scaled by 255).
bool validColour(const std::vector<double>& e, std::size_t first, std::size_t count) {
  if (count != 3 && count != 4) return false;  // 1 is a colour-map index; 2 reads past the line
  bool whole = true;
  for (std::size_t k = first; k < first + 3; ++k) whole = whole && std::floor(e[k]) == e[k];
  for (std::size_t k = first; k < first + 3; ++k) {
    const double byte = whole ? e[k] : e[k] * 255;
    if (!(byte >= 0 && byte < 256)) return false;
  }
  return true;
}

}  // namespace

std::string precheckOff(const std::string& text) {
  TextStream in(text);
  // The header, as File_header_OFF's operator>> reads it: comment lines, the keyword (and the
  // character after it), then the counts.
  char c = 0;
  while ((in >> c) && c == '#') skipLine(in);
  if (!in) return "";  // an empty file: CGAL says so
  std::string keyword(1, c);
  while (keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c)))
    keyword += c;
  if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0 &&
      keyword != "OFF" && keyword != "COFF")
    return "unsupported OFF variant '" + keyword + "' (relpos reads OFF and COFF)";
  if (keyword != "OFF" && keyword != "COFF") return "";  // not OFF at all: CGAL refuses it
  const bool colours = keyword == "COFF";
  if (!skipComments(in) || !std::isdigit(static_cast<unsigned char>(in.peek())))
    return in && in.peek() == 'B' ? "binary OFF is not supported (write it as ASCII OFF)"
                                  : "bad OFF header (expected the vertex, face and edge counts)";
  long long vertices = 0, faces = 0, edges = 0;
  if (!(in >> vertices >> faces >> edges) || vertices > INT_MAX || faces < 0 || faces > INT_MAX ||
      std::llabs(edges) > INT_MAX / 2)
    return "bad OFF header (expected the vertex, face and edge counts)";
  if (static_cast<double>(vertices) + static_cast<double>(faces) > kMaxElements)
    return "too large: the OFF header counts " + std::to_string(vertices) + " vertices and " +
           std::to_string(faces) + " faces";

  std::vector<double> e;
  bool vertex_colours = false;  // CGAL's flag: once set, every vertex's colour is read
  for (long long v = 0; v < vertices; ++v) {
    if (!nextLine(in, &e))
      return "the OFF header counts " + std::to_string(vertices) + " vertices, the file holds " +
             std::to_string(v);
    if (e.size() < 3) return "OFF vertex " + std::to_string(v) + " has fewer than 3 coordinates";
    if (!colours) continue;  // without the C, CGAL ignores what follows the coordinates
    vertex_colours = vertex_colours || e.size() > 3;
    if (vertex_colours && !validColour(e, 3, e.size() - 3))
      return "OFF vertex " + std::to_string(v) +
             " has a bad colour (3 or 4 components, 0-255 or 0-1)";
  }
  bool face_colours = false;
  for (long long f = 0; f < faces; ++f) {
    if (!nextLine(in, &e))
      return "the OFF header counts " + std::to_string(faces) + " faces, the file holds " +
             std::to_string(f);
    const std::string face = "OFF face " + std::to_string(f);
    // (An empty line would make CGAL read the previous face's colour from it.)
    if (e.empty()) return face + " has no vertex count";
    // CGAL sizes the face from its first number before it reads the indices.
    if (!isIndex(e[0], static_cast<double>(e.size())))
      return face + ": its vertex count does not match the indices on its line";
    const auto n = static_cast<std::size_t>(e[0]);
    for (std::size_t k = 1; k <= n; ++k)
      if (!isIndex(e[k], static_cast<double>(vertices)))
        return face + " refers to a missing vertex (index " + number(e[k]) + "; the mesh has " +
               std::to_string(vertices) + ")";
    if (!colours) continue;
    face_colours = face_colours || e.size() > n + 1;
    if (face_colours && !validColour(e, n + 1, e.size() - n - 1))
      return face + " has a bad colour (3 or 4 components, 0-255 or 0-1)";
  }
  return "";
}

}  // namespace relpos::collision::detail
