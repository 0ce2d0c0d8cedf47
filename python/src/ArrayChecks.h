#pragma once
/// @file ArrayChecks.h
/// @brief Turning Python values into checked arrays and vectors of `real`: the errors name the
/// argument, a wrong type raises TypeError, a wrong shape or a non-finite value ValueError.

#include <ThyrixLite/Vector2.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>

namespace thyrix::python {

/// A C-contiguous array of `real` with the values of @p value (a numpy array or a nested
/// sequence of numbers; integers are converted, booleans, complex numbers, strings and objects
/// are not).
/// @throws pybind11::type_error naming @p name if it is not an array of real numbers
pybind11::array_t<real, pybind11::array::c_style> realArray(pybind11::handle value,
                                                            const std::string& name);

/// Checks that @p array has exactly @p shape.
/// @throws pybind11::value_error naming @p name and both shapes otherwise
void requireShape(const pybind11::array& array, std::initializer_list<pybind11::ssize_t> shape,
                  const std::string& name);

/// Checks that every value of @p values is finite.
/// @throws pybind11::value_error naming @p name and the first bad index otherwise
void requireFinite(std::span<const real> values, const std::string& name);

/// realArray() of shape @p shape, all finite.
pybind11::array_t<real, pybind11::array::c_style> checkedArray(
    pybind11::handle value, std::initializer_list<pybind11::ssize_t> shape,
    const std::string& name);

/// A finite 2-vector from a pair of numbers (a tuple, a list or an array of shape (2,)).
Vector2 toVector2(pybind11::handle value, const std::string& name);

/// A finite number, as `real`.
/// @throws pybind11::value_error naming @p name if it is not finite
real finiteReal(double value, const std::string& name);

/// The tuple (x, y).
pybind11::tuple fromVector2(Vector2 value);

/// A read-only numpy copy of @p values.
pybind11::array_t<real> copyOf(std::span<const real> values);

}  // namespace thyrix::python
