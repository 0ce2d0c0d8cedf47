#include "SymmetricEigen.h"

#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace thyrix {

namespace {

// One plane rotation of the pair (x, y) by the sine s and tau = s / (1 + cos).
inline void rotate(double& x, double& y, double s, double tau) {
  const double g = x;
  const double h = y;
  x = g - s * (h + g * tau);
  y = h + s * (g - h * tau);
}

}  // namespace

void symmetricEigen(std::size_t n, std::span<const double> matrix, std::span<double> values,
                    std::span<double> vectors) {
  if (matrix.size() != n * n)
    throw InvalidArgument("symmetricEigen.matrix", "must hold n * n = " + std::to_string(n * n) +
                                                       " values (got " +
                                                       std::to_string(matrix.size()) + ")");
  if (values.size() != n)
    throw InvalidArgument("symmetricEigen.values", "must hold n = " + std::to_string(n) +
                                                       " values (got " +
                                                       std::to_string(values.size()) + ")");
  if (vectors.size() != n * n)
    throw InvalidArgument("symmetricEigen.vectors", "must hold n * n values");
  for (double x : matrix)
    if (!std::isfinite(x)) throw InvalidArgument("symmetricEigen.matrix", "must be finite");

  std::vector<double> a(matrix.begin(), matrix.end());  // upper triangle, rotated to zero
  std::vector<double> v(n * n, 0.0);  // V transposed: eigenvector k is row k, contiguous
  std::vector<double> d(n), b(n), z(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    v[i * n + i] = 1;
    d[i] = b[i] = a[i * n + i];
  }
  const auto at = [&](std::size_t i, std::size_t j) -> double& { return a[i * n + j]; };
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) off += std::abs(at(p, q));
    if (off == 0) break;
    // Early sweeps rotate only the large elements, which saves rotations that later ones undo.
    const double threshold = sweep < 3 ? 0.2 * off / static_cast<double>(n * n) : 0.0;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q) {
        const double apq = at(p, q);
        const double g = 100 * std::abs(apq);
        if (sweep > 3 && std::abs(d[p]) + g == std::abs(d[p]) &&
            std::abs(d[q]) + g == std::abs(d[q])) {
          at(p, q) = 0;  // below the diagonal's precision
          continue;
        }
        if (std::abs(apq) <= threshold) continue;
        double h = d[q] - d[p];
        double t;
        if (std::abs(h) + g == std::abs(h)) {
          t = apq / h;
        } else {
          const double theta = 0.5 * h / apq;
          t = 1 / (std::abs(theta) + std::sqrt(1 + theta * theta));
          if (theta < 0) t = -t;
        }
        const double c = 1 / std::sqrt(1 + t * t);
        const double s = t * c;
        const double tau = s / (1 + c);
        h = t * apq;
        z[p] -= h;
        z[q] += h;
        d[p] -= h;
        d[q] += h;
        at(p, q) = 0;
        for (std::size_t j = 0; j < p; ++j) rotate(at(j, p), at(j, q), s, tau);
        for (std::size_t j = p + 1; j < q; ++j) rotate(at(p, j), at(j, q), s, tau);
        for (std::size_t j = q + 1; j < n; ++j) rotate(at(p, j), at(q, j), s, tau);
        for (std::size_t j = 0; j < n; ++j) rotate(v[p * n + j], v[q * n + j], s, tau);
      }
    }
    for (std::size_t p = 0; p < n; ++p) {
      b[p] += z[p];
      d[p] = b[p];
      z[p] = 0;
    }
  }

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return d[i] < d[j]; });
  for (std::size_t k = 0; k < n; ++k) {
    values[k] = d[order[k]];
    for (std::size_t row = 0; row < n; ++row) vectors[row * n + k] = v[order[k] * n + row];
  }
}

}  // namespace thyrix
