#pragma once
/// @file SymmetricEigen.h
/// @brief Eigenvalues and eigenvectors of a real symmetric matrix (cyclic Jacobi).

#include <cstddef>
#include <span>

namespace thyrix {

/// Diagonalizes the symmetric @p n x @p n matrix @p matrix (row-major; only its upper triangle
/// is read) by cyclic Jacobi rotations: `matrix = V diag(values) V^T` with V orthogonal.
/// Jacobi is slower than QR on a tridiagonal form but simple and accurate to the last bits
/// of the small eigenvalues, which CMA-ES divides by.
/// @param n the matrix's order
/// @param matrix the n * n values, row-major
/// @param values receives the n eigenvalues, in increasing order
/// @param vectors receives V row-major: column j is the unit eigenvector of `values[j]`
/// @throws InvalidArgument naming "symmetricEigen.matrix" (size not n * n or a value not
///         finite), "symmetricEigen.values" or "symmetricEigen.vectors" (wrong size)
void symmetricEigen(std::size_t n, std::span<const double> matrix, std::span<double> values,
                    std::span<double> vectors);

}  // namespace thyrix
