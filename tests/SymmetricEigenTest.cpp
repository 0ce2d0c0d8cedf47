// symmetricEigen() against closed forms: a 2 x 2 rotation, the tridiagonal matrix of the
// discrete Laplacian, and the reconstruction A = V diag(values) V^T of a random matrix.

#include <Evolution/SymmetricEigen.h>
#include <ThyrixLite/InvalidArgument.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace thyrix {
namespace {

TEST(SymmetricEigenTest, TwoByTwo) {
  // [[2, 1], [1, 2]]: eigenvalues 1 and 3, eigenvectors (1, -1) / sqrt 2 and (1, 1) / sqrt 2.
  const std::vector<double> a = {2, 1, 1, 2};
  std::vector<double> values(2), vectors(4);
  symmetricEigen(2, a, values, vectors);
  EXPECT_NEAR(values[0], 1, 1e-15);
  EXPECT_NEAR(values[1], 3, 1e-15);
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(std::abs(vectors[0]), s, 1e-15);  // column 0
  EXPECT_NEAR(vectors[0] * vectors[2], -0.5, 1e-15);
  EXPECT_NEAR(vectors[1] * vectors[3], 0.5, 1e-15);  // column 1: same signs
}

TEST(SymmetricEigenTest, DiscreteLaplacianHasItsClosedFormSpectrum) {
  // tridiag(-1, 2, -1) of size n: eigenvalues 2 - 2 cos(k pi / (n + 1)), k = 1..n.
  const std::size_t n = 40;
  std::vector<double> a(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    a[i * n + i] = 2;
    if (i + 1 < n) a[i * n + i + 1] = a[(i + 1) * n + i] = -1;
  }
  std::vector<double> values(n), vectors(n * n);
  symmetricEigen(n, a, values, vectors);
  for (std::size_t k = 1; k <= n; ++k)
    EXPECT_NEAR(values[k - 1],
                2 - 2 * std::cos(static_cast<double>(k) * std::numbers::pi / (n + 1.0)), 1e-13);
}

TEST(SymmetricEigenTest, RandomMatrixIsRebuiltFromOrthonormalVectors) {
  const std::size_t n = 25;
  std::mt19937 engine(7);
  std::vector<double> a(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      a[i * n + j] = a[j * n + i] = static_cast<double>(engine() % 2001) / 1000 - 1;
  std::vector<double> values(n), v(n * n);
  symmetricEigen(n, a, values, v);
  for (std::size_t k = 1; k < n; ++k) EXPECT_LE(values[k - 1], values[k]);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      double rebuilt = 0, dot = 0;
      for (std::size_t k = 0; k < n; ++k) {
        rebuilt += v[i * n + k] * values[k] * v[j * n + k];
        dot += v[k * n + i] * v[k * n + j];
      }
      EXPECT_NEAR(rebuilt, a[i * n + j], 1e-12);
      EXPECT_NEAR(dot, i == j ? 1 : 0, 1e-12);
    }
  }
}

TEST(SymmetricEigenTest, RefusesWrongSizesAndNonFiniteValues) {
  std::vector<double> values(2), vectors(4);
  EXPECT_THROW(symmetricEigen(2, std::vector<double>(3, 0.0), values, vectors), InvalidArgument);
  EXPECT_THROW(symmetricEigen(2, std::vector<double>{1, NAN, NAN, 1}, values, vectors),
               InvalidArgument);
  std::vector<double> short_(1);
  EXPECT_THROW(symmetricEigen(2, std::vector<double>(4, 0.0), short_, vectors), InvalidArgument);
}

}  // namespace
}  // namespace thyrix
