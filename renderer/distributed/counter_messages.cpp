#include "renderer/distributed/counter_messages.h"

#include "renderer/distributed/message_bytes.h"

namespace isotrace {

std::string encode_counters(const CounterTotals& totals) {
    MessageWriter out;
    out.put(totals.camera_rays).put(totals.secondary_rays).put(totals.shadow_rays).put(totals.nan_samples);
    out.put(std::uint64_t(totals.geometry.size()));
    for (const auto& [type, counts] : totals.geometry) out.put_string(type).put(counts);
    out.put(std::uint64_t(totals.named.size()));
    for (const auto& [name, value] : totals.named) out.put_string(name).put(value);
    return out.take();
}

CounterTotals decode_counters(std::string_view bytes) {
    MessageReader in(bytes);
    CounterTotals totals;
    totals.camera_rays = in.get<std::uint64_t>();
    totals.secondary_rays = in.get<std::uint64_t>();
    totals.shadow_rays = in.get<std::uint64_t>();
    totals.nan_samples = in.get<std::uint64_t>();
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
        std::string type = in.get_string();
        totals.geometry[type] = in.get<GeometryTypeCounts>();
    }
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
        std::string name = in.get_string();
        totals.named[name] = in.get<std::uint64_t>();
    }
    return totals;
}

void add_counters(CounterTotals& into, const CounterTotals& from) {
    into.camera_rays += from.camera_rays;
    into.secondary_rays += from.secondary_rays;
    into.shadow_rays += from.shadow_rays;
    into.nan_samples += from.nan_samples;
    for (const auto& [type, counts] : from.geometry) {
        GeometryTypeCounts& sum = into.geometry[type];
        sum.tests += counts.tests;
        sum.candidate_hits += counts.candidate_hits;
        sum.closest_hits += counts.closest_hits;
        sum.counts_tests = counts.counts_tests;
    }
    for (const auto& [name, value] : from.named) into.named[name] += value;
}

}  // namespace isotrace
