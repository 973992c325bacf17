#pragma once
// MemoryBudget: the memory a run may use, charged with an estimate before each large, input-sized allocation
// (film and AOV buffers, texture pixels, generated elements), so that input asking for too much is refused with
// the figure (InputError, exit 2) instead of ending in std::bad_alloc or the kernel's OOM killer.
#include <atomic>
#include <cstdint>
#include <string>

#include "renderer/core/input_error.h"

namespace isotrace {

class MemoryBudget {
public:
    // The default limit: 80 % of physical memory.
    MemoryBudget();
    explicit MemoryBudget(std::uint64_t limit_bytes);

    static std::uint64_t physical_memory_bytes();
    static std::uint64_t default_limit_bytes();

    // Adds `bytes` for `what` ("film of 65536x65536 pixels with 4 AOVs"). Throws InputError at `where`/`field`
    // with the estimate, the total and the limit when the total would exceed the limit (and charges nothing).
    // Thread-safe.
    void charge(std::uint64_t bytes, const std::string& what, const SourceLocation& where = {},
                const std::string& field = {});

    // Gives back `bytes` charged earlier, for working memory that is freed again (see MemoryReservation).
    void release(std::uint64_t bytes) { charged_.fetch_sub(bytes); }

    std::uint64_t limit_bytes() const { return limit_; }
    std::uint64_t charged_bytes() const { return charged_.load(); }

private:
    std::uint64_t limit_;
    std::atomic<std::uint64_t> charged_{0};
};

// A charge for as long as the object lives: working memory that is freed again (a deformer's), so that what comes
// after it is not refused for memory no longer in use.
class MemoryReservation {
public:
    MemoryReservation(MemoryBudget& budget, std::uint64_t bytes, const std::string& what, const SourceLocation& where = {},
                      const std::string& field = {})
        : budget_(&budget), bytes_(bytes) {
        budget.charge(bytes, what, where, field);
    }
    ~MemoryReservation() {
        if (budget_) budget_->release(bytes_);
    }
    MemoryReservation(MemoryReservation&& other) noexcept : budget_(other.budget_), bytes_(other.bytes_) {
        other.budget_ = nullptr;
    }
    MemoryReservation(const MemoryReservation&) = delete;
    MemoryReservation& operator=(const MemoryReservation&) = delete;
    MemoryReservation& operator=(MemoryReservation&&) = delete;

private:
    MemoryBudget* budget_;
    std::uint64_t bytes_;
};

// "27.4 GB" (powers of 1000, three significant digits) for messages.
std::string format_bytes(std::uint64_t bytes);

// Product of sizes that saturates at UINT64_MAX instead of wrapping (estimates of absurd input stay absurd).
std::uint64_t saturating_product(std::initializer_list<std::uint64_t> factors);

// Sum of sizes or costs that saturates at UINT64_MAX instead of wrapping, likewise.
std::uint64_t saturating_sum(std::initializer_list<std::uint64_t> terms);

}  // namespace isotrace
