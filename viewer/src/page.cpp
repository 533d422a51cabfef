// The page (relpos/viewer/page.hpp): the scene's JSON and the compiled-in script in one HTML file.
#include "relpos/viewer/page.hpp"

#include <nlohmann/json.hpp>

#include "scene_json.hpp"
#include "viewer_script.hpp"

namespace relpos::viewer {
namespace {

std::string escapeHtml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// JSON inside <script>: "</" would let a name end the element; "<\/" is the same JSON string.
std::string scriptSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += '\\';
  }
  return out;
}

constexpr const char* kStyle = R"css(
html, body { margin: 0; height: 100%; font: 13px/1.4 system-ui, sans-serif; color: #1d2430; }
#viewport { position: fixed; inset: 0 0 0 340px; }
#panel { position: fixed; top: 0; bottom: 0; left: 0; width: 324px; overflow-y: auto;
         padding: 8px; background: #fff; border-right: 1px solid #d5d8de; }
h1 { font-size: 16px; margin: 4px 0; word-break: break-word; }
.status { color: #4a5260; margin-bottom: 4px; }
.message { color: #8a4b00; margin-bottom: 6px; white-space: pre-wrap; }
.branch { display: block; margin: 2px 0; cursor: pointer; }
.parameter { margin: 8px 0; }
.parameter .name { font-weight: 600; display: inline; }
.parameter input[type=range] { width: 100%; }
.motion, .note, .legend { color: #5b6372; font-size: 12px; }
.buttons { margin: 8px 0; display: flex; gap: 10px; align-items: center; flex-wrap: wrap; }
#pose { background: #f4f5f7; padding: 6px; font-size: 12px; white-space: pre-wrap; }
#message { position: fixed; left: 350px; top: 8px; color: #a00; }
)css";

}  // namespace

bool writePage(const Problem& problem, const Solution& solution, const Report& report,
               const ViewOptions& options, std::string* html, std::vector<Diagnostic>* errors,
               std::vector<Diagnostic>* warnings) {
  nlohmann::json scene;
  if (!detail::sceneJson(problem, solution, report, options, &scene, errors, warnings))
    return false;
  const std::string title = "relpos — " + (problem.name.empty() ? "view" : problem.name);
  html->clear();
  *html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  *html += "<meta name=\"generator\" content=\"relpos view\">\n";
  *html += "<title>" + escapeHtml(title) + "</title>\n<style>" + kStyle + "</style>\n";
  *html += "</head>\n<body>\n<div id=\"panel\"></div>\n<div id=\"viewport\"></div>\n";
  *html += "<div id=\"message\"></div>\n";
  // error_handler_t::replace: a name with invalid UTF-8 is written, not thrown about.
  *html += "<script id=\"relpos-scene\" type=\"application/json\">" +
           scriptSafe(scene.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)) +
           "</script>\n";
  *html += "<script>";
  *html += detail::viewerScript();
  *html += "</script>\n</body>\n</html>\n";
  return true;
}

}  // namespace relpos::viewer
