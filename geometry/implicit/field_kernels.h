#pragma once
// Every kernel a blob group may use, as one list of their concrete classes: the scene names, make_field_function and
// the plugin's summary read their kName from it, and with_kernel calls a function with the kernel as its concrete
// (final) class, so that the march's kernel calls inline. A new kernel is its class (with kName) and a place here.
#include <cstddef>
#include <optional>
#include <string_view>

#include "geometry/implicit/blinn_exponential.h"
#include "geometry/implicit/field_function.h"
#include "geometry/implicit/kim_sextic.h"
#include "geometry/implicit/murakami_quartic.h"
#include "geometry/implicit/nishimura_quadratic.h"
#include "geometry/implicit/wyvill_sextic.h"

namespace isotrace {

template <class... Kernels>
struct KernelList {
    static constexpr std::size_t kCount = sizeof...(Kernels);
    static constexpr std::string_view kNames[kCount] = {Kernels::kName...};
};

// In the metacube paper's table order.
using FieldKernels = KernelList<BlinnExponential, NishimuraQuadratic, MurakamiQuartic, WyvillSextic, KimSextic>;

// The position of the kernel called `name` in FieldKernels, if any.
constexpr std::optional<std::size_t> field_kernel_index(std::string_view name) {
    for (std::size_t i = 0; i < FieldKernels::kCount; ++i)
        if (FieldKernels::kNames[i] == name) return i;
    return std::nullopt;
}

namespace field_kernels_detail {

template <class F, class First, class... Rest>
decltype(auto) with_kernel(KernelList<First, Rest...>, std::size_t index, const FieldFunction& kernel, F& f) {
    if constexpr (sizeof...(Rest) == 0) {
        return f(static_cast<const First&>(kernel));
    } else {
        if (index == 0) return f(static_cast<const First&>(kernel));
        return with_kernel(KernelList<Rest...>{}, index - 1, kernel, f);
    }
}

}  // namespace field_kernels_detail

// f(kernel as its concrete class), `index` being the kernel's field_kernel_index.
template <class F>
decltype(auto) with_kernel(std::size_t index, const FieldFunction& kernel, F&& f) {
    return field_kernels_detail::with_kernel(FieldKernels{}, index, kernel, f);
}

}  // namespace isotrace
