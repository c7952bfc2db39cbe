#include "nckit/report/report_page.hpp"

#include "viewer_bundle.hpp"

namespace nckit {

namespace {

std::string escape_html(std::string_view text) {
    std::string out;
    for (char c : text) {
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

void add_charts(Payload& payload, const std::vector<ReportChart>& charts) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t c = 0; c < charts.size(); ++c) {
        const ReportChart& chart = charts[c];
        nlohmann::json series = nlohmann::json::array();
        for (std::size_t s = 0; s < chart.series.size(); ++s) {
            const std::string key = "chart" + std::to_string(c) + "_" + std::to_string(s);
            payload.add_f64(key + "_x", chart.series[s].x);
            payload.add_f64(key + "_y", chart.series[s].y);
            series.push_back({{"name", chart.series[s].name}, {"x", key + "_x"}, {"y", key + "_y"}});
        }
        nlohmann::json lines = nlohmann::json::array();
        for (const auto& [label, value] : chart.y_lines) lines.push_back({{"label", label}, {"value", value}});
        list.push_back({{"title", chart.title},
                        {"x_label", chart.x_label},
                        {"y_label", chart.y_label},
                        {"equal_axes", chart.equal_axes},
                        {"series", series},
                        {"y_lines", lines},
                        {"log_y", chart.log_y}});
    }
    payload.header["charts"] = list;
}

// Characters of base64 per piece of the page's data: a multiple of 4 (each piece decodes on
// its own); 1 MiB keeps a 17 MB page at 17 pieces.
constexpr std::size_t data_piece_chars = std::size_t{1} << 20;

}  // namespace

std::string render_report_html(const ReportPage& page) {
    Payload payload;
    payload.header["title"] = page.title;
    payload.header["kind"] = page.kind;
    nlohmann::json figures = nlohmann::json::array();
    for (const auto& [name, value] : page.figures) figures.push_back({name, value});
    payload.header["figures"] = figures;
    add_charts(payload, page.charts);
    if (page.tool_path) add_tool_path(payload, *page.tool_path);
    const std::string data = base64(gzip(payload.pack()));

    std::string html;
    html.reserve(data.size() + report_detail::viewer_js.size() + report_detail::viewer_css.size() + 1024);
    html += "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>";
    html += escape_html(page.title);
    html += "</title>\n<meta name=\"generator\" content=\"nckit\">\n<style>\n";
    html += report_detail::viewer_css;
    html += "</style>\n</head>\n<body>\n<div id=\"app\"";
    // The drawn vertices, so the script can start the 3D view's renderer before it reads the data.
    if (page.tool_path) html += " data-vertices=\"" + std::to_string(page.tool_path->report.vertices.size()) + "\"";
    html += "></div>\n";
    // The script first: it starts the WebGL work while the browser still reads the data, and
    // reads the data when the document is parsed.
    html += "<script>\n";
    html += report_detail::viewer_js;
    html += "\n</script>\n";
    // base64 has no '<', so the data cannot end its element early. It comes in pieces of
    // whole base64 quads, each followed by a call that hands the pieces read so far to the
    // script, which unpacks them on a worker thread while the browser still reads the rest.
    html += "<div id=\"nckit-data\" hidden>\n";
    for (std::size_t at = 0; at < data.size(); at += data_piece_chars) {
        html += "<script type=\"application/octet-stream\">";
        html += std::string_view(data).substr(at, data_piece_chars);
        html += "</script><script>self.nckitData&&nckitData()</script>\n";
    }
    html += "</div>\n</body></html>\n";
    return html;
}

}  // namespace nckit
