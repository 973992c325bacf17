#!/usr/bin/env python3
"""Independent calculation of the FLIP values that flip_test.cpp expects.

Plain Python (no numpy), straight from the papers' formulas: the 2-D filter kernels are built and applied
whole (no separable shortcut), pixel by pixel, with the border pixels repeated. Run it to reprint the numbers:
    python3 renderer/image_compare/flip_expected_values.py
"""
import math

PPD = 3840 * math.pi / 180
WHITE = (0.950428545, 1.0, 1.088900371)
RGB2XYZ = ((10135552 / 24577794, 8788810 / 24577794, 4435075 / 24577794),
           (2613072 / 12288897, 8788810 / 12288897, 887015 / 12288897),
           (1425312 / 73733382, 8788810 / 73733382, 70074185 / 73733382))
XYZ2RGB = ((3.241003275, -1.537398934, -0.498615861),
           (-0.969224334, 1.875930071, 0.041554224),
           (0.055639423, -0.204011202, 1.057148933))


def mat(m, v):
    return tuple(sum(m[r][c] * v[c] for c in range(3)) for r in range(3))


def srgb_decode(v):
    return ((v + 0.055) / 1.055) ** 2.4 if v > 0.04045 else v / 12.92


def ycxcz(rgb):
    x, y, z = (a / w for a, w in zip(mat(RGB2XYZ, rgb), WHITE))
    return (116 * y - 16, 500 * (x - y), 200 * (y - z))


def hunt_lab_of_ycxcz(c):
    y = (c[0] + 16) / 116
    xyz = ((y + c[1] / 500) * WHITE[0], y, (y - c[2] / 200) * WHITE[2])
    rgb = tuple(min(max(v, 0.0), 1.0) for v in mat(XYZ2RGB, xyz))
    d = 6 / 29
    f = lambda t: t ** (1 / 3) if t > d ** 3 else t / (3 * d * d) + 4 / 29
    fx, fy, fz = (f(a / w) for a, w in zip(mat(RGB2XYZ, rgb), WHITE))
    L, a, b = 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)
    return (L, 0.01 * L * a, 0.01 * L * b)


def hyab(p, q):
    return abs(p[0] - q[0]) + math.hypot(p[1] - q[1], p[2] - q[2])


CMAX = hyab(hunt_lab_of_ycxcz(ycxcz((0, 1, 0))), hunt_lab_of_ycxcz(ycxcz((0, 0, 1)))) ** 0.7


def colour_error(lab_ref, lab_test):
    e = hyab(lab_ref, lab_test) ** 0.7
    return 0.95 / (0.4 * CMAX) * e if e < 0.4 * CMAX else 0.95 + (e - 0.4 * CMAX) / (CMAX - 0.4 * CMAX) * 0.05


def csf_kernel(terms):
    r = math.ceil(3 * math.sqrt(0.04 / (2 * math.pi ** 2)) * PPD)
    k = {}
    for i in range(-r, r + 1):
        for j in range(-r, r + 1):
            z = ((i / PPD) ** 2 + (j / PPD) ** 2)
            k[(i, j)] = sum(a * math.sqrt(math.pi / b) * math.exp(-math.pi ** 2 * z / b) for a, b in terms)
    s = sum(k.values())
    return {key: v / s for key, v in k.items()}


CSF = [csf_kernel([(1, 0.0047)]), csf_kernel([(1, 0.0053)]), csf_kernel([(34.1, 0.04), (13.5, 0.025)])]


def feature_kernel(kind):
    sd = 0.5 * 0.082 * PPD
    r = math.ceil(3 * sd)
    k = {}
    for i in range(-r, r + 1):
        for j in range(-r, r + 1):
            g = math.exp(-(i * i + j * j) / (2 * sd * sd))
            k[(i, j)] = -i * g if kind == 'edge' else (i * i / (sd * sd) - 1) * g
    pos = sum(v for v in k.values() if v > 0)
    neg = -sum(v for v in k.values() if v < 0)
    return {key: (v / pos if v > 0 else v / neg) for key, v in k.items()}


EDGE, POINT = feature_kernel('edge'), feature_kernel('point')


def correlate(plane, w, h, kernel, x, y, transpose=False):
    total = 0.0
    for (i, j), weight in kernel.items():
        if transpose:
            i, j = j, i
        xx, yy = min(max(x + i, 0), w - 1), min(max(y + j, 0), h - 1)
        total += weight * plane[yy][xx]
    return total


def flip_at(ref, test, x, y):
    """LDR-FLIP at one pixel of two linear-RGB images given as rows of (r, g, b)."""
    h, w = len(ref), len(ref[0])
    parts = []
    for image in (ref, test):
        opp = [[ycxcz(p) for p in row] for row in image]
        filtered = tuple(correlate([[p[c] for p in row] for row in opp], w, h, CSF[c], x, y) for c in range(3))
        lum = [[(p[0] + 16) / 116 for p in row] for row in opp]
        edge = math.hypot(correlate(lum, w, h, EDGE, x, y), correlate(lum, w, h, EDGE, x, y, True))
        point = math.hypot(correlate(lum, w, h, POINT, x, y), correlate(lum, w, h, POINT, x, y, True))
        parts.append((hunt_lab_of_ycxcz(filtered), edge, point))
    colour = colour_error(parts[0][0], parts[1][0])
    feature = (max(abs(parts[0][1] - parts[1][1]), abs(parts[0][2] - parts[1][2])) / math.sqrt(2)) ** 0.5
    return colour, feature, colour ** (1 - feature)


def uniform_flip(ref_rgb, test_rgb):
    """LDR-FLIP of two uniform linear-RGB images: the filters keep a constant, the features are 0."""
    return colour_error(hunt_lab_of_ycxcz(ycxcz(ref_rgb)), hunt_lab_of_ycxcz(ycxcz(test_rgb)))


K0, K1, K3, K4, K5 = 0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14


def aces(x):
    return min(max((K0 * x * x + K1 * x) / (K3 * x * x + K4 * x + K5), 0.0), 1.0)


def aces_inverse(t):
    c0 = (K1 - K4 * t) / (K0 - K3 * t)
    c1 = -K5 * t / (K0 - K3 * t)
    return -0.5 * c0 + math.sqrt(0.25 * c0 * c0 - c1)


if __name__ == '__main__':
    print('cmax = %.10f' % CMAX)
    srgb = lambda *v: tuple(srgb_decode(c) for c in v)
    print('uniform grey sRGB 0.5 -> 0.6: %.10f' % uniform_flip(srgb(0.5, 0.5, 0.5), srgb(0.6, 0.6, 0.6)))
    print('uniform sRGB (0.8,0.2,0.2) -> (0.7,0.3,0.2): %.10f' % uniform_flip(srgb(0.8, 0.2, 0.2), srgb(0.7, 0.3, 0.2)))
    print('uniform black -> white: %.10f' % uniform_flip((0, 0, 0), (1, 1, 1)))

    # Edge: 32x8, black left of x = 16; the reference is white right of it, the test sRGB grey 0.5.
    grey = srgb_decode(0.5)
    ref = [[(0, 0, 0) if x < 16 else (1, 1, 1) for x in range(32)] for _ in range(8)]
    test = [[(0, 0, 0) if x < 16 else (grey, grey, grey) for x in range(32)] for _ in range(8)]
    for x in (2, 12, 15, 16, 20, 29):
        print('edge x=%d: colour %.10f feature %.10f flip %.10f' % ((x,) + flip_at(ref, test, x, 4)))

    # HDR: grey thirds 0.25 | 1 | 3, the test 1.1 times as bright.
    x085 = aces_inverse(0.85)
    start, stop = math.log2(x085 / 3), math.log2(x085 / 1)
    print('x(0.85) = %.10f start %.10f stop %.10f' % (x085, start, stop))
    for v in (0.25, 1.0, 3.0):
        errors = [uniform_flip((aces(2 ** e * v),) * 3, (aces(2 ** e * 1.1 * v),) * 3) for e in (start, stop)]
        print('hdr grey %.2f: per exposure %s, max %.10f' % (v, ['%.10f' % e for e in errors], max(errors)))
