#pragma once
// isotrace diff --fail METRIC=VALUE: thresholds a CI job can gate on.
#include <map>
#include <string>
#include <vector>

namespace isotrace::cli {

// The metrics isotrace diff reports, in output order.
const std::vector<std::string>& diff_metric_names();

// Throws InputError naming `option` unless `metric` is one of them (with a suggestion for a near miss).
void require_metric_name(const std::string& metric, const std::string& option);

// Whether a larger value means more alike (PSNR, SSIM): such a metric fails below its threshold, the others above.
bool higher_is_better(const std::string& metric);

struct Threshold {
    std::string metric;
    double value = 0;
};

// Parses "flip=0.05"; throws InputError naming --fail for an unknown metric (with a suggestion) or a value that is
// not a finite number.
Threshold parse_threshold(const std::string& text);

// One line per threshold the values break ("flip 0.0612 > 0.05"); empty when all hold.
std::vector<std::string> broken_thresholds(const std::vector<Threshold>& thresholds,
                                           const std::map<std::string, double>& values);

}  // namespace isotrace::cli
