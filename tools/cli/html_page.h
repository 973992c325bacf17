#pragma once
// Pieces of the self-contained HTML pages of isotrace bench --report and isotrace benchmark --report.
#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace isotrace::cli {

// <!DOCTYPE html> to the opening <body> and an <h1> of `title`, with the pages' shared style.
std::string html_page_start(const std::string& title);

// <td>text</td> (or another tag), the text escaped.
std::string html_cell(const std::string& text, const char* tag = "td");

// A two-column table of `facts[key]` under each title; strings as they are, other values as JSON, "unknown" for
// absent keys.
std::string html_facts_table(const nlohmann::json& facts,
                             const std::vector<std::pair<const char*, const char*>>& title_and_key);

}  // namespace isotrace::cli
