#include "renderer/core/did_you_mean.h"

#include <algorithm>
#include <cctype>

namespace isotrace {
namespace {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// Optimal-string-alignment distance: edits are insert, delete, substitute and swap of neighbours,
// so the common typo "ACESgc" is one edit away from "ACEScg".
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

}  // namespace

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
    // The edit distance costs |word| x |candidate|: no suggestion for words no one types by hand.
    constexpr std::size_t kMaxWordLength = 256;
    if (word.empty() || word.size() > kMaxWordLength) return "";
    // About one typo per three characters; beyond that a suggestion is more confusing than helpful.
    const std::size_t max_distance = std::max<std::size_t>(1, word.size() / 3);
    const std::string lower_word = lowercase(word);

    const std::string* best = nullptr;
    std::size_t best_distance = max_distance + 1;
    for (const std::string& candidate : candidates) {
        // The distance is at least the difference in length: skip the computation when that is already too far.
        const std::size_t length_gap = std::max(word.size(), candidate.size()) - std::min(word.size(), candidate.size());
        if (length_gap >= best_distance) continue;
        const std::size_t distance = edit_distance(lower_word, lowercase(candidate));
        if (distance < best_distance) {
            best = &candidate;
            best_distance = distance;
        }
    }
    return best ? " (did you mean \"" + *best + "\"?)" : "";
}

}  // namespace isotrace
