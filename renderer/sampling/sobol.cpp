#include "renderer/sampling/sobol.h"

#include <array>
#include <bit>
#include <cassert>

#include "renderer/sampling/owen_scramble.h"

namespace isotrace {
namespace {

// A Sobol' dimension is defined by a primitive polynomial over GF(2) of degree s,
//   x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1   (the a_j packed into `inner_coefficients`, a_1 most significant),
// and s free odd integers m_1..m_s with m_k < 2^k. These rows are dimensions 2..4 of Joe & Kuo's file.
struct SobolPolynomial {
    int degree;
    uint32_t inner_coefficients;
    std::array<uint32_t, 3> initial_m;
};

constexpr std::array<SobolPolynomial, kSobolDimensions - 1> kPolynomials = {{
    {1, 0, {1, 0, 0}},
    {2, 1, {1, 3, 0}},
    {3, 1, {1, 3, 1}},
}};

using GeneratorMatrix = std::array<uint32_t, 32>;  // column k: direction number for index bit k

// The remaining m_k follow from Bratley & Fox's recurrence (as documented by Joe & Kuo):
//   m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^(s-1) a_(s-1) m_(k-s+1) ^ 2^s m_(k-s) ^ m_(k-s),
// and the k-th direction number (1-based) is m_k / 2^k, i.e. m_k << (32 - k) in 0.32 fixed point.
constexpr GeneratorMatrix generator_from_polynomial(const SobolPolynomial& p) {
    std::array<uint32_t, 32> m{};
    for (int k = 0; k < 32; ++k) {
        if (k < p.degree) {
            m[k] = p.initial_m[k];
            continue;
        }
        uint32_t next = m[k - p.degree] ^ (m[k - p.degree] << p.degree);
        for (int j = 1; j < p.degree; ++j) {
            if ((p.inner_coefficients >> (p.degree - 1 - j)) & 1u) next ^= m[k - j] << j;
        }
        m[k] = next;
    }
    GeneratorMatrix columns{};
    for (int k = 0; k < 32; ++k) columns[k] = m[k] << (31 - k);
    return columns;
}

// Dimension 0 has no polynomial: all m_k = 1, which is the van der Corput sequence (bit reversal).
constexpr GeneratorMatrix van_der_corput_generator() {
    GeneratorMatrix columns{};
    for (int k = 0; k < 32; ++k) columns[k] = 1u << (31 - k);
    return columns;
}

constexpr std::array<GeneratorMatrix, kSobolDimensions> build_generators() {
    std::array<GeneratorMatrix, kSobolDimensions> generators{};
    generators[0] = van_der_corput_generator();
    for (uint32_t d = 1; d < kSobolDimensions; ++d) generators[d] = generator_from_polynomial(kPolynomials[d - 1]);
    return generators;
}

// The matrix-vector product over GF(2) is linear in the index bits, so it splits into one lookup per index
// byte: table[byte position][byte value] = XOR of the columns that byte selects. Bit reversal is linear too:
// the tables are indexed by the reversed index and hold reversed columns (bit b of the reversed index is
// index bit 31 - b). An entry holds all four dimensions, laid out as one vector, so a point is four 16-byte
// loads and three XORs (16 KiB of tables), not sixteen scalar loads assembled into a vector. (Plain words rather
// than Uint4 so that the tables are built at compile time.)
struct alignas(16) FourDimensions {
    std::array<uint32_t, kSobolDimensions> values;
};
using ByteTables = std::array<std::array<FourDimensions, 256>, 4>;

constexpr ByteTables bit_reversed_byte_tables() {
    const std::array<GeneratorMatrix, kSobolDimensions> generators = build_generators();
    ByteTables tables{};
    for (std::size_t position = 0; position < 4; ++position)
        for (uint32_t byte = 0; byte < 256; ++byte)
            for (std::size_t d = 0; d < kSobolDimensions; ++d) {
                uint32_t value = 0;
                for (std::size_t bit = 0; bit < 8; ++bit)
                    if ((byte >> bit) & 1u) value ^= reverse_bits(generators[d][31 - (position * 8 + bit)]);
                tables[position][byte].values[d] = value;
            }
    return tables;
}

constexpr ByteTables kByteTables = bit_reversed_byte_tables();

}  // namespace

Uint4 sobol_point_bit_reversed(uint32_t reversed_index) {
    static_assert(kSobolDimensions == 4);
    const auto entry = [](std::size_t position, uint32_t byte) {
        return std::bit_cast<Uint4>(kByteTables[position][byte]);
    };
    return entry(0, reversed_index & 0xFFu) ^ entry(1, (reversed_index >> 8) & 0xFFu) ^
           entry(2, (reversed_index >> 16) & 0xFFu) ^ entry(3, reversed_index >> 24);
}

uint32_t sobol_sample_bit_reversed(uint32_t reversed_index, uint32_t dimension) {
    assert(dimension < kSobolDimensions);
    return sobol_point_bit_reversed(reversed_index)[dimension];
}

uint32_t sobol_sample(uint32_t index, uint32_t dimension) {
    return reverse_bits(sobol_sample_bit_reversed(reverse_bits(index), dimension));
}

}  // namespace isotrace
