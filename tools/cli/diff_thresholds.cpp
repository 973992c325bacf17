#include "tools/cli/diff_thresholds.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_error.h"

namespace isotrace::cli {

const std::vector<std::string>& diff_metric_names() {
    static const std::vector<std::string> names = {"rmse", "relmse", "psnr", "ssim", "flip"};
    return names;
}

void require_metric_name(const std::string& metric, const std::string& option) {
    const std::vector<std::string>& names = diff_metric_names();
    if (std::find(names.begin(), names.end(), metric) != names.end()) return;
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    throw InputError({}, option, "unknown metric \"" + metric + "\"" + did_you_mean(metric, names) + "; metrics: " + list);
}

bool higher_is_better(const std::string& metric) { return metric == "psnr" || metric == "ssim"; }

Threshold parse_threshold(const std::string& text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos)
        throw InputError({}, "--fail", "expected METRIC=VALUE (for example flip=0.05), got \"" + text + "\"");
    Threshold threshold{text.substr(0, equals), 0};
    require_metric_name(threshold.metric, "--fail");
    const std::string number = text.substr(equals + 1);
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), threshold.value);
    if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(threshold.value))
        throw InputError({}, "--fail", "the threshold for " + threshold.metric + " must be a finite number, got \"" +
                                           number + "\"");
    return threshold;
}

std::vector<std::string> broken_thresholds(const std::vector<Threshold>& thresholds,
                                           const std::map<std::string, double>& values) {
    std::vector<std::string> broken;
    for (const Threshold& t : thresholds) {
        const auto found = values.find(t.metric);
        if (found == values.end()) continue;
        const double value = found->second;
        const bool below = higher_is_better(t.metric);
        // NaN breaks every threshold.
        if (below ? !(value >= t.value) : !(value <= t.value)) {
            char line[160];
            std::snprintf(line, sizeof line, "%s %.6g %s %.6g", t.metric.c_str(), value, below ? "<" : ">", t.value);
            broken.emplace_back(line);
        }
    }
    return broken;
}

}  // namespace isotrace::cli
