#pragma once
// BlobGroup::with_kernel, for the files that call it (the group's point queries and its cell sweeps).
#include "geometry/implicit/blinn_exponential.h"
#include "geometry/implicit/blob_group.h"
#include "geometry/implicit/kim_sextic.h"
#include "geometry/implicit/murakami_quartic.h"
#include "geometry/implicit/nishimura_quadratic.h"
#include "geometry/implicit/wyvill_sextic.h"

namespace isotrace {

template <class F>
decltype(auto) BlobGroup::with_kernel(F&& f) const {
    switch (kernel_kind_) {
        case KernelKind::Blinn: return f(static_cast<const BlinnExponential&>(*kernel_));
        case KernelKind::Nishimura: return f(static_cast<const NishimuraQuadratic&>(*kernel_));
        case KernelKind::Murakami: return f(static_cast<const MurakamiQuartic&>(*kernel_));
        case KernelKind::Wyvill: return f(static_cast<const WyvillSextic&>(*kernel_));
        case KernelKind::Kim: break;
    }
    return f(static_cast<const KimSextic&>(*kernel_));
}

}  // namespace isotrace
