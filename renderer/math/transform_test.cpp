#include "renderer/math/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace isotrace {
namespace {

using Matrix = Transform::Matrix;

void expect_near(const Vec3d& actual, const Vec3d& expected, double tolerance = 1e-12) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

void expect_matrix_near(const Matrix& actual, const Matrix& expected, double tolerance = 1e-12) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(actual[i][j], expected[i][j], tolerance) << "[" << i << "][" << j << "]";
}

Matrix identity() {
    Matrix m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

// A general affine transform: rotation, non-uniform scale, shear and translation.
Matrix general_affine() {
    return {{{2.0, 0.5, 0.0, 1.0}, {0.0, 1.5, -0.25, -2.0}, {0.3, 0.0, 0.8, 3.0}, {0.0, 0.0, 0.0, 1.0}}};
}

TEST(Transform, DefaultIsIdentity) {
    const Transform t;
    EXPECT_TRUE(t.is_identity());
    EXPECT_EQ(t.matrix(), identity());
    EXPECT_EQ(t.inverse().matrix(), identity());
    EXPECT_EQ(t.point(Vec3d{1, 2, 3}), Vec3d(1, 2, 3));
    EXPECT_EQ(t.determinant(), 1.0);
}

TEST(Transform, TranslateMovesPointsButNotVectorsOrNormals) {
    const Transform t = Transform::translate({1, -2, 3});
    EXPECT_EQ(t.point(Vec3d{1, 1, 1}), Vec3d(2, -1, 4));
    EXPECT_EQ(t.vector(Vec3d{1, 1, 1}), Vec3d(1, 1, 1));
    EXPECT_EQ(t.normal(Vec3d{0, 0, 1}), Vec3d(0, 0, 1));
    EXPECT_EQ(t.inverse().point(Vec3d{2, -1, 4}), Vec3d(1, 1, 1));
    EXPECT_FALSE(t.is_identity());
}

TEST(Transform, ScaleAndItsInverse) {
    const Transform s = Transform::scale({2, 4, -0.5});
    EXPECT_EQ(s.point(Vec3d{1, 1, 1}), Vec3d(2, 4, -0.5));
    EXPECT_EQ(s.vector(Vec3d{1, 1, 1}), Vec3d(2, 4, -0.5));
    EXPECT_EQ(s.inverse().point(Vec3d{2, 4, -0.5}), Vec3d(1, 1, 1));
    EXPECT_DOUBLE_EQ(s.determinant(), -4.0);  // negative: a mirror
    EXPECT_THROW(Transform::scale({1, 0, 1}), std::invalid_argument);
}

TEST(Transform, NormalsUseTheInverseTranspose) {
    // Squash y by 2: the plane x + y = 0 (normal (1, 1, 0)) becomes x + 2y = 0, normal ∝ (1, 2, 0).
    const Transform s = Transform::scale({1, 0.5, 1});
    const Vec3d n = s.normal(Vec3d{1, 1, 0});
    EXPECT_NEAR(n.y / n.x, 2.0, 1e-15);
    EXPECT_EQ(n.z, 0.0);
    // Normals stay perpendicular to transformed tangents for a general affine transform.
    const Transform a = Transform::from_matrix(general_affine());
    const Vec3d tangent{0.3, -1.2, 0.7}, other{1.1, 0.4, -0.6};
    const Vec3d normal = cross(tangent, other);
    EXPECT_NEAR(dot(a.normal(normal), a.vector(tangent)), 0.0, 1e-12);
    EXPECT_NEAR(dot(a.normal(normal), a.vector(other)), 0.0, 1e-12);
    // Not normalised.
    EXPECT_NEAR(length(Transform::scale({2, 2, 2}).normal(Vec3d{0, 0, 1})), 0.5, 1e-15);
}

TEST(Transform, RotateIsCounterClockwiseAboutTheAxis) {
    expect_near(Transform::rotate({0, 0, 1}, 90).point(Vec3d{1, 0, 0}), {0, 1, 0});
    expect_near(Transform::rotate({1, 0, 0}, 90).point(Vec3d{0, 1, 0}), {0, 0, 1});
    expect_near(Transform::rotate({0, 1, 0}, 90).point(Vec3d{0, 0, 1}), {1, 0, 0});
    expect_near(Transform::rotate({0, 0, 5}, 180).point(Vec3d{1, 2, 3}), {-1, -2, 3});  // axis need not be unit
    // 120 degrees about the diagonal cycles the axes.
    expect_near(Transform::rotate({1, 1, 1}, 120).point(Vec3d{1, 0, 0}), {0, 1, 0});
    const Transform r = Transform::rotate({0.3, -0.5, 0.8}, 37);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
    expect_near(r.inverse().point(r.point(Vec3d{1, 2, 3})), {1, 2, 3});
    EXPECT_THROW(Transform::rotate({0, 0, 0}, 10), std::invalid_argument);
}

TEST(Transform, CompositionAppliesTheRightOperandFirst) {
    const Transform t = Transform::translate({10, 0, 0});
    const Transform s = Transform::scale({2, 2, 2});
    EXPECT_EQ((t * s).point(Vec3d{1, 1, 1}), Vec3d(12, 2, 2));  // scale, then translate
    EXPECT_EQ((s * t).point(Vec3d{1, 1, 1}), Vec3d(22, 2, 2));  // translate, then scale
    // The inverse of a product is the product of the inverses in reverse order.
    const Transform r = Transform::rotate({1, 2, 3}, 40);
    const Transform chain = t * r * s;
    expect_matrix_near(multiply(chain.matrix(), chain.inverse().matrix()), identity());
    expect_matrix_near(chain.inverse().matrix(), (s.inverse() * r.inverse() * t.inverse()).matrix());
}

TEST(Transform, InverseSwapsTheMatrices) {
    const Transform a = Transform::from_matrix(general_affine());
    EXPECT_EQ(a.inverse().inverse().matrix(), a.matrix());
    expect_matrix_near(multiply(a.matrix(), a.inverse().matrix()), identity());
    expect_matrix_near(multiply(a.inverse().matrix(), a.matrix()), identity());
    const Vec3d p{0.5, -7, 2};
    expect_near(a.inverse().point(a.point(p)), p);
    expect_near(a.inverse().vector(a.vector(p)), p);
}

// The unchecked inverse of an accepted matrix is bit for bit the checked one's.
TEST(Transform, InverseOfAcceptedIsTheInverseOfFromMatrix) {
    const Transform checked = Transform::from_matrix(general_affine()).inverse();
    const Transform unchecked = Transform::inverse_of_accepted(general_affine());
    EXPECT_EQ(unchecked.matrix(), checked.matrix());
    EXPECT_EQ(unchecked.inverse().matrix(), checked.inverse().matrix());
}

TEST(Transform, InversePointAndNormalAreTheInverseTransforms) {
    const Transform a = Transform::from_matrix(general_affine());
    const Vec3d p{0.5, -7, 2};
    EXPECT_EQ(a.inverse_point(p), a.inverse().point(p));
    EXPECT_EQ(a.inverse_normal(p), a.inverse().normal(p));
    expect_near(a.inverse_point(a.point(p)), p);
}

TEST(Transform, FromMatrixRejectsNonAffineSingularAndNonFinite) {
    Matrix projective = identity();
    projective[3][2] = 1;
    EXPECT_THROW(Transform::from_matrix(projective), std::invalid_argument);
    Matrix w2 = identity();
    w2[3][3] = 2;
    EXPECT_THROW(Transform::from_matrix(w2), std::invalid_argument);
    Matrix flat = identity();
    flat[2][2] = 0;  // squashes z
    EXPECT_THROW(Transform::from_matrix(flat), std::invalid_argument);
    Matrix dependent = identity();
    dependent[1] = {2, 0, 0, 5};  // row 1 = 2 * row 0 (plus translation)
    EXPECT_THROW(Transform::from_matrix(dependent), std::invalid_argument);
    Matrix nan = identity();
    nan[0][3] = std::nan("");
    EXPECT_THROW(Transform::from_matrix(nan), std::invalid_argument);
    try {
        Transform::from_matrix(projective);
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "matrix is not affine: the last row must be [0, 0, 0, 1]");
    }
    try {
        Transform::from_matrix(flat);
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "matrix is singular");
    }
}

TEST(Transform, FromMatrixAcceptsSmallButRegularScales) {
    // Micrometre units: a uniform scale of 1e-6 is regular even though its determinant is 1e-18.
    Matrix micro = identity();
    for (int i = 0; i < 3; ++i) micro[i][i] = 1e-6;
    const Transform t = Transform::from_matrix(micro);
    expect_near(t.inverse().point(Vec3d{1e-6, 2e-6, 3e-6}), {1, 2, 3}, 1e-9);
    Matrix big = identity();
    for (int i = 0; i < 3; ++i) big[i][i] = 1e8;
    EXPECT_NO_THROW(Transform::from_matrix(big));
    // Columns of ordinary size that are nearly dependent are singular for all practical purposes.
    Matrix nearly_flat = identity();
    nearly_flat[0][1] = 1;
    nearly_flat[1][1] = 1e-14;  // column 1 = column 0 + a 1e-14 nudge
    EXPECT_THROW(Transform::from_matrix(nearly_flat), std::invalid_argument);
}

TEST(Transform, LookAtLooksDownMinusZWithYUp) {
    const Vec3d eye{1, 2, 3};
    const Transform camera = Transform::look_at(eye, {1, 2, -7}, {0, 1, 0});  // looking along world -z
    expect_near(camera.point(Vec3d{0, 0, 0}), eye);
    expect_near(camera.vector(Vec3d{0, 0, -1}), {0, 0, -1});
    expect_near(camera.vector(Vec3d{1, 0, 0}), {1, 0, 0});
    expect_near(camera.vector(Vec3d{0, 1, 0}), {0, 1, 0});

    const Transform side = Transform::look_at({0, 0, 0}, {5, 0, 0}, {0, 1, 0});  // looking along world +x
    expect_near(side.vector(Vec3d{0, 0, -1}), {1, 0, 0});
    expect_near(side.vector(Vec3d{0, 1, 0}), {0, 1, 0});
    expect_near(side.vector(Vec3d{1, 0, 0}), {0, 0, 1});  // right-handed: right = forward x up
    EXPECT_NEAR(side.determinant(), 1.0, 1e-14);
}

TEST(Transform, LookAtOrthogonalisesUpAndMapsTheTarget) {
    const Vec3d eye{0.278, 0.273, -0.8}, target{0.4, 0.1, 0.5};
    const Transform camera = Transform::look_at(eye, target, {0.2, 1, 0.1});  // up not perpendicular
    const Vec3d forward = normalize(target - eye);
    expect_near(camera.vector(Vec3d{0, 0, -1}), forward);
    // The target lies on the camera's -z axis at its distance.
    expect_near(camera.inverse().point(target), {0, 0, -length(target - eye)});
    EXPECT_NEAR(camera.similarity_scale(), 1.0, 1e-12);
    EXPECT_NEAR(camera.determinant(), 1.0, 1e-12);
    EXPECT_GT(dot(camera.vector(Vec3d{0, 1, 0}), Vec3d(0.2, 1, 0.1)), 0.0);  // up keeps its sense
}

TEST(Transform, LookAtRejectsDegenerateInput) {
    EXPECT_THROW(Transform::look_at({1, 1, 1}, {1, 1, 1}, {0, 1, 0}), std::invalid_argument);
    EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 5, 0}, {0, 1, 0}), std::invalid_argument);
    EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, -5, 0}, {0, 2, 0}), std::invalid_argument);
    EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 0, -1}, {0, 0, 0}), std::invalid_argument);
}

TEST(Transform, SimilarityScaleAcceptsRotationUniformScaleAndTranslation) {
    EXPECT_EQ(Transform().similarity_scale(), 1.0);
    EXPECT_DOUBLE_EQ(Transform::scale({3, 3, 3}).similarity_scale(), 3.0);
    const Transform similarity =
        Transform::translate({4, 5, 6}) * Transform::rotate({1, -2, 0.5}, 73) * Transform::scale({0.25, 0.25, 0.25});
    EXPECT_NEAR(similarity.similarity_scale(), 0.25, 1e-14);
    EXPECT_DOUBLE_EQ(Transform::scale({-2, -2, -2}).similarity_scale(), 2.0);  // a mirror preserves angles too
    EXPECT_NEAR(Transform::scale({0.001, 0.001, 0.001}).similarity_scale(), 0.001, 1e-18);
}

TEST(Transform, SimilarityScaleRejectsNonUniformScaleAndShear) {
    EXPECT_EQ(Transform::scale({1, 2, 1}).similarity_scale(), 0.0);
    EXPECT_EQ((Transform::rotate({0, 0, 1}, 30) * Transform::scale({1, 1, 1.001})).similarity_scale(), 0.0);
    EXPECT_EQ((Transform::scale({2, 1, 1}) * Transform::rotate({0, 0, 1}, 30)).similarity_scale(), 0.0);
    Matrix shear = identity();
    shear[0][1] = 0.1;
    EXPECT_EQ(Transform::from_matrix(shear).similarity_scale(), 0.0);
    EXPECT_EQ(Transform::from_matrix(general_affine()).similarity_scale(), 0.0);
}

TEST(Transform, Determinant) {
    EXPECT_DOUBLE_EQ(Transform::scale({2, 3, 4}).determinant(), 24.0);
    EXPECT_DOUBLE_EQ((Transform::translate({9, 9, 9}) * Transform::scale({2, 3, 4})).determinant(), 24.0);
    EXPECT_NEAR(Transform::rotate({1, 1, 0}, 33).determinant(), 1.0, 1e-14);
    // general_affine's linear part, expanded by hand.
    const double expected = 2.0 * (1.5 * 0.8 - (-0.25) * 0.0) - 0.5 * (0.0 * 0.8 - (-0.25) * 0.3) + 0.0;
    EXPECT_DOUBLE_EQ(Transform::from_matrix(general_affine()).determinant(), expected);
}

TEST(Transform, FloatOverloadsMatchDouble) {
    const Transform a = Transform::from_matrix(general_affine());
    const Vec3f p{1.5f, -2.0f, 0.25f};
    const Vec3d pd(p);
    EXPECT_EQ(a.point(p), Vec3f(a.point(pd)));
    EXPECT_EQ(a.vector(p), Vec3f(a.vector(pd)));
    EXPECT_EQ(a.normal(p), Vec3f(a.normal(pd)));
}

// A temporary's matrix is handed out as a copy: `const Matrix& m = t.inverse().matrix();` once bound a reference
// into the dead temporary, which clang's builds happened to read intact and GCC's read as zeros (every placement
// refused as singular).
TEST(Transform, AMatrixOfATemporaryIsACopy) {
    static_assert(std::is_same_v<decltype(std::declval<Transform>().matrix()), Transform::Matrix>);
    static_assert(std::is_same_v<decltype(std::declval<const Transform&>().matrix()), const Transform::Matrix&>);
    const Transform to_world = Transform::translate({1, 2, 3}) * Transform::scale({2, 2, 2});
    const Transform::Matrix& inverse = to_world.inverse().matrix();  // lifetime-extended copy
    EXPECT_EQ(inverse, to_world.inverse().matrix());
    EXPECT_EQ(inverse[0][0], 0.5);
}

}  // namespace
}  // namespace isotrace
