// ns per solve, Sturm bisection vs the monotone-interval finder, by degree, on random polynomials with a root in
// [0,1] and without one. Run: build/bin/polynomial_benchmark
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/polynomial/monotone_root_finder.h"
#include "tests/support/sturm_sequence.h"

namespace isotrace {
namespace {

constexpr int kPolynomialsPerSet = 256;

// Products of random linear factors and complex pairs. With a root: one real root uniform in [0,1] and the others
// anywhere in [−2,3]. Without: every real root outside [0,1].
std::vector<Polynomial> random_polynomials(int degree, bool with_root_inside) {
    std::mt19937_64 random(degree * 2 + with_root_inside);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::vector<Polynomial> polynomials;
    while (static_cast<int>(polynomials.size()) < kPolynomialsPerSet) {
        Polynomial p{1};
        int remaining = degree;
        if (with_root_inside) {
            p = p * Polynomial{-uniform(random), 1};
            --remaining;
        }
        for (; remaining >= 2 && uniform(random) < 0.5; remaining -= 2) {
            const double centre = -2 + 5 * uniform(random), spread = 0.05 + uniform(random);
            p = p * Polynomial{centre * centre + spread * spread, -2 * centre, 1};
        }
        for (; remaining > 0; --remaining) {
            double root = -2 + 5 * uniform(random);
            if (!with_root_inside && root >= 0 && root <= 1) root += root < 0.5 ? -1.05 : 1.05;
            p = p * Polynomial{-root, 1};
        }
        polynomials.push_back(p);
    }
    return polynomials;
}

template <typename Solve>
void run(benchmark::State& state, Solve solve) {
    const std::vector<Polynomial> polynomials = random_polynomials(static_cast<int>(state.range(0)), state.range(1));
    std::size_t next = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(solve(polynomials[next]));
        next = (next + 1) % polynomials.size();
    }
    state.SetLabel(state.range(1) ? "root in [0,1]" : "no root in [0,1]");
}

void SturmFirstRoot(benchmark::State& state) {
    run(state, [](const Polynomial& p) {
        const PolynomialRoots roots = sturm_roots(p, 0, 1);
        return roots.empty() ? -1.0 : roots[0].t;
    });
}

void MonotoneFirstRoot(benchmark::State& state) {
    run(state, [](const Polynomial& p) {
        const std::optional<PolynomialRoot> root = first_root(p, 0, 1);
        return root ? root->t : -1.0;
    });
}

void MonotoneAllRoots(benchmark::State& state) {
    run(state, [](const Polynomial& p) { return all_roots(p, 0, 1).size(); });
}

void arguments(benchmark::internal::Benchmark* benchmark) {
    for (int with_root : {1, 0})
        for (int degree : {2, 4, 6, 8, 10}) benchmark->Args({degree, with_root});
    benchmark->ArgNames({"degree", "root"});
}

BENCHMARK(SturmFirstRoot)->Apply(arguments);
BENCHMARK(MonotoneFirstRoot)->Apply(arguments);
BENCHMARK(MonotoneAllRoots)->Apply(arguments);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
