#pragma once
// A test helper for the SVG and HTML writers of isotrace bench --report.
#include <gtest/gtest.h>

#include <regex>
#include <stack>
#include <string>

namespace isotrace::cli {

// Every start tag has its end tag, in order (self-closing tags count as both); no stray '<' or '&' in text.
inline testing::AssertionResult well_formed_markup(const std::string& text) {
    std::stack<std::string> open;
    const std::regex tag("<(/?)([a-zA-Z][a-zA-Z0-9]*)[^<>]*?(/?)>|<!DOCTYPE[^>]*>|<");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), tag); it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        if (m.str() == "<") return testing::AssertionFailure() << "stray '<' at " << m.position();
        if (m.str(2).empty()) continue;  // the doctype
        const std::string name = m.str(2);
        if (name == "meta") continue;  // an HTML void element
        if (!m.str(3).empty()) continue;
        if (m.str(1).empty()) {
            open.push(name);
        } else {
            if (open.empty() || open.top() != name)
                return testing::AssertionFailure()
                       << "</" << name << "> closes " << (open.empty() ? "nothing" : "<" + open.top() + ">");
            open.pop();
        }
    }
    if (!open.empty()) return testing::AssertionFailure() << "<" << open.top() << "> is never closed";
    const std::regex bad_entity("&(?!(amp|lt|gt|quot|#39);)");
    if (std::regex_search(text, bad_entity)) return testing::AssertionFailure() << "an unescaped '&'";
    return testing::AssertionSuccess();
}

}  // namespace isotrace::cli
