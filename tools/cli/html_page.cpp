#include "tools/cli/html_page.h"

#include "tools/cli/svg_plot.h"

namespace isotrace::cli {

std::string html_page_start(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xml_escaped(title) +
           "</title>\n"
           "<style>\nbody{font-family:sans-serif;margin:2em;color:#222;max-width:1100px}\n"
           "table{border-collapse:collapse;margin:1em 0}th,td{border:1px solid #ccc;padding:3px 8px;text-align:left}\n"
           "td{font-variant-numeric:tabular-nums}figure{margin:1em 0}pre{background:#f6f6f6;padding:1em;overflow:auto}\n"
           "</style>\n</head>\n<body>\n<h1>" +
           xml_escaped(title) + "</h1>\n";
}

std::string html_cell(const std::string& text, const char* tag) {
    return std::string("<") + tag + ">" + xml_escaped(text) + "</" + tag + ">";
}

std::string html_facts_table(const nlohmann::json& facts,
                             const std::vector<std::pair<const char*, const char*>>& title_and_key) {
    std::string html = "<table class=\"machine\">\n";
    for (const auto& [title, key] : title_and_key) {
        const nlohmann::json& value = facts.contains(key) ? facts[key] : nlohmann::json("unknown");
        html += "<tr>" + html_cell(title, "th") + html_cell(value.is_string() ? value.get<std::string>() : value.dump()) +
                "</tr>\n";
    }
    return html + "</table>\n";
}

}  // namespace isotrace::cli
