#pragma once
// sin and cos of one angle from one call: glibc's sincos shares the range reduction and returns sin's and cos's own
// values, bit for bit, so code may use it wherever both are needed without changing a result.
#include <cmath>

namespace isotrace {

struct SinCos {
    double sin, cos;
};

inline SinCos sin_cos(double angle) {
    SinCos r;
    ::sincos(angle, &r.sin, &r.cos);
    return r;
}

}  // namespace isotrace
