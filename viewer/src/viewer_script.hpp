#pragma once
// The page's script: three.js and viewer/web/src bundled by esbuild at build time
// (viewer/CMakeLists.txt), compiled in by viewer/cmake/embed_script.cmake.
namespace relpos::viewer::detail {

const char* viewerScript();

}  // namespace relpos::viewer::detail
