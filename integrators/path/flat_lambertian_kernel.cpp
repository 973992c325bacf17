// Which build of the packet kernel runs (flat_lambertian_packets.h): chosen once per process.
#include "integrators/path/flat_lambertian_packets.h"
#include "renderer/core/avx2_module.h"

#ifndef ISOTRACE_PACKETS_AVX2_MODULE
#error "the build must define ISOTRACE_PACKETS_AVX2_MODULE (the AVX2 kernel module's file name)"
#endif

namespace isotrace {
namespace {

struct ChosenKernel {
    FlatLambertianKernel kernel = &baseline_isa::trace_flat_lambertian_paths;
    const char* name = "baseline x86-64";
};

// The module only speeds the render up: where it is missing or cannot load, the baseline kernel computes the
// same bits.
ChosenKernel choose() {
    const FlatLambertianKernel kernel =
        avx2_module_build<FlatLambertianKernel>(ISOTRACE_PACKETS_AVX2_MODULE, kFlatLambertianKernelEntry);
    if (!kernel) return {};
    return {kernel, "avx2"};
}

const ChosenKernel& chosen() {
    static const ChosenKernel kernel = choose();
    return kernel;
}

}  // namespace

FlatLambertianKernel flat_lambertian_kernel() { return chosen().kernel; }

const char* flat_lambertian_kernel_name() { return chosen().name; }

}  // namespace isotrace
