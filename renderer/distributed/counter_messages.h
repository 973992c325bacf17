#pragma once
// A rank's render counters as message bytes, and their sum over the ranks (the statistics of a distributed
// render count every rank's rays).
#include <string>
#include <string_view>

#include "renderer/core/render_counters.h"

namespace isotrace {

std::string encode_counters(const CounterTotals& totals);
CounterTotals decode_counters(std::string_view bytes);
void add_counters(CounterTotals& into, const CounterTotals& from);

}  // namespace isotrace
