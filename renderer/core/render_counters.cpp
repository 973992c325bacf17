#include "renderer/core/render_counters.h"

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace isotrace::counters {
namespace detail {

__thread ThreadBlock* thread_block __attribute__((tls_model("initial-exec"))) = nullptr;

void ThreadBlock::clear() {
    for (auto& c : rays) c.store(0, std::memory_order_relaxed);
    nan_samples.store(0, std::memory_order_relaxed);
    for (auto& type : geometry)
        for (auto& c : type) c.store(0, std::memory_order_relaxed);
    for (auto& c : named) c.store(0, std::memory_order_relaxed);
}

}  // namespace detail

namespace {

using detail::Counter;
using detail::kMaxGeometryTypes;
using detail::kMaxNamedCounters;
using detail::local_block;
using detail::ThreadBlock;

constexpr const char* kOverflowCounter = "counters.overflow";

std::uint64_t read(const Counter& counter) { return counter.load(std::memory_order_relaxed); }

struct Registry {
    std::mutex mutex;
    std::vector<std::unique_ptr<ThreadBlock>> blocks;  // owned here so counts survive thread exit
    std::vector<std::string> type_names;
    std::vector<bool> type_counts_tests;
    std::vector<std::string> counter_names;
    std::vector<int> counter_totals;  // per named counter: the slot it also adds into, or −1
};

Registry& registry() {
    static Registry instance;
    return instance;
}

}  // namespace

detail::ThreadBlock* detail::new_block() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.blocks.push_back(std::make_unique<ThreadBlock>());
    return r.blocks.back().get();
}

int geometry_type_slot(const std::string& type_name, bool counts_tests) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (std::size_t i = 0; i < r.type_names.size(); ++i)
        if (r.type_names[i] == type_name) return int(i);
    if (r.type_names.size() == kMaxGeometryTypes) throw std::logic_error("too many geometry types for counters");
    r.type_names.push_back(type_name);
    r.type_counts_tests.push_back(counts_tests);
    return int(r.type_names.size() - 1);
}

int named_counter_slot(const std::string& name, int total_slot) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (total_slot >= int(r.counter_names.size())) throw std::logic_error("counter total registered after its part");
    for (std::size_t i = 0; i < r.counter_names.size(); ++i)
        if (r.counter_names[i] == name) return int(i);
    // Full: every further name adds to one overflow counter rather than failing the render.
    if (r.counter_names.size() + 1 == kMaxNamedCounters) {
        r.counter_names.push_back(kOverflowCounter);
        r.counter_totals.push_back(-1);
    }
    if (r.counter_names.size() == kMaxNamedCounters) return kMaxNamedCounters - 1;
    r.counter_names.push_back(name);
    r.counter_totals.push_back(total_slot);
    return int(r.counter_names.size() - 1);
}

CounterTotals totals() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    CounterTotals result;
    for (const auto& block : r.blocks) {
        result.camera_rays += read(block->rays[int(RayKind::Camera)]);
        result.secondary_rays += read(block->rays[int(RayKind::Secondary)]);
        result.shadow_rays += read(block->rays[int(RayKind::Shadow)]);
        result.nan_samples += read(block->nan_samples);
    }
    for (std::size_t slot = 0; slot < r.type_names.size(); ++slot) {
        GeometryTypeCounts counts;
        counts.counts_tests = r.type_counts_tests[slot];
        for (const auto& block : r.blocks) {
            counts.tests += read(block->geometry[slot][0]);
            counts.candidate_hits += read(block->geometry[slot][1]);
            counts.closest_hits += read(block->geometry[slot][2]);
        }
        result.geometry[r.type_names[slot]] = counts;
    }
    std::vector<std::uint64_t> sums(r.counter_names.size(), 0);
    for (std::size_t slot = 0; slot < sums.size(); ++slot)
        for (const auto& block : r.blocks) sums[slot] += read(block->named[slot]);
    // A total's slot precedes its parts': from the last slot down, a part is complete before it is added.
    for (std::size_t slot = sums.size(); slot-- > 0;)
        if (r.counter_totals[slot] >= 0) sums[std::size_t(r.counter_totals[slot])] += sums[slot];
    for (std::size_t slot = 0; slot < sums.size(); ++slot) result.named[r.counter_names[slot]] = sums[slot];
    return result;
}

void reset() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (auto& block : r.blocks) block->clear();
}

}  // namespace isotrace::counters
