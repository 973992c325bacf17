#include "renderer/core/memory_budget.h"

#include <unistd.h>

#include <cstdio>
#include <limits>

namespace isotrace {

MemoryBudget::MemoryBudget() : MemoryBudget(default_limit_bytes()) {}

MemoryBudget::MemoryBudget(std::uint64_t limit_bytes) : limit_(limit_bytes) {}

std::uint64_t MemoryBudget::physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0) return std::numeric_limits<std::uint64_t>::max();  // unknown: no limit
    return saturating_product({std::uint64_t(pages), std::uint64_t(page_size)});
}

std::uint64_t MemoryBudget::default_limit_bytes() {
    const std::uint64_t physical = physical_memory_bytes();
    return physical == std::numeric_limits<std::uint64_t>::max() ? physical : physical / 5 * 4;
}

void MemoryBudget::charge(std::uint64_t bytes, const std::string& what, const SourceLocation& where,
                          const std::string& field) {
    std::uint64_t before = charged_.load();
    for (;;) {
        if (before > limit_ || bytes > limit_ - before)
            throw InputError(where, field,
                             what + " needs about " + format_bytes(bytes) +
                                 (before > 0 ? " (on top of " + format_bytes(before) + " already needed)" : "") +
                                 ", more than the memory limit of " + format_bytes(limit_) +
                                 " (--max-memory; the default is 80 % of physical memory)");
        if (charged_.compare_exchange_weak(before, before + bytes)) return;
    }
}

std::string format_bytes(std::uint64_t bytes) {
    static constexpr const char* kUnits[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
    double value = double(bytes);
    int unit = 0;
    while (value >= 1000 && unit < 6) {
        value /= 1000;
        ++unit;
    }
    char text[32];
    if (unit == 0) std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    else std::snprintf(text, sizeof text, "%.3g %s", value, kUnits[unit]);
    return text;
}

std::uint64_t saturating_product(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t product = 1;
    for (const std::uint64_t f : factors)
        if (__builtin_mul_overflow(product, f, &product)) return std::numeric_limits<std::uint64_t>::max();
    return product;
}

std::uint64_t saturating_sum(std::initializer_list<std::uint64_t> terms) {
    std::uint64_t sum = 0;
    for (const std::uint64_t t : terms)
        if (__builtin_add_overflow(sum, t, &sum)) return std::numeric_limits<std::uint64_t>::max();
    return sum;
}

}  // namespace isotrace
