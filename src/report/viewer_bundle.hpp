#pragma once
// The viewer's script and style sheet, bundled from web/ by esbuild at build time
// (web/embed.mjs writes viewer_bundle.cpp into the build folder).
#include <string_view>

namespace nckit::report_detail {

extern const std::string_view viewer_js;
extern const std::string_view viewer_css;

}  // namespace nckit::report_detail
