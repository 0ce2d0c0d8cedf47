#include "ArrayChecks.h"

#include <cmath>
#include <sstream>

namespace py = pybind11;

namespace thyrix::python {

namespace {

std::string shapeText(const py::ssize_t* shape, std::size_t dimensions) {
  std::ostringstream text;
  text << '(';
  for (std::size_t i = 0; i < dimensions; ++i) text << (i ? ", " : "") << shape[i];
  text << (dimensions == 1 ? ",)" : ")");
  return text.str();
}

}  // namespace

py::array_t<real, py::array::c_style> realArray(py::handle value, const std::string& name) {
  py::array array;
  try {
    array = py::array::ensure(value);
  } catch (const py::error_already_set&) {
    array = py::array();
  }
  if (!array) throw py::type_error(name + " must be an array of real numbers");
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(name + " must be an array of real numbers, not of dtype " +
                         std::string(py::str(array.dtype())));
  return py::array_t<real, py::array::c_style | py::array::forcecast>::ensure(array);
}

void requireShape(const py::array& array, std::initializer_list<py::ssize_t> shape,
                  const std::string& name) {
  bool same = static_cast<std::size_t>(array.ndim()) == shape.size();
  for (std::size_t i = 0; same && i < shape.size(); ++i)
    same = array.shape()[i] == shape.begin()[i];
  if (!same)
    throw py::value_error(name + " must have shape " + shapeText(shape.begin(), shape.size()) +
                          ", not " +
                          shapeText(array.shape(), static_cast<std::size_t>(array.ndim())));
}

void requireFinite(std::span<const real> values, const std::string& name) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw py::value_error(name + " must be finite (entry " + std::to_string(i) + " is " +
                            std::to_string(static_cast<double>(values[i])) + ")");
}

py::array_t<real, py::array::c_style> checkedArray(py::handle value,
                                                   std::initializer_list<py::ssize_t> shape,
                                                   const std::string& name) {
  auto array = realArray(value, name);
  requireShape(array, shape, name);
  requireFinite({array.data(), static_cast<std::size_t>(array.size())}, name);
  return array;
}

Vector2 toVector2(py::handle value, const std::string& name) {
  const auto array = checkedArray(value, {2}, name);
  return {array.data()[0], array.data()[1]};
}

real finiteReal(double value, const std::string& name) {
  if (!std::isfinite(value))
    throw py::value_error(name + " must be finite (got " + std::to_string(value) + ")");
  return static_cast<real>(value);
}

py::tuple fromVector2(Vector2 value) {
  return py::make_tuple(static_cast<double>(value.x), static_cast<double>(value.y));
}

py::array_t<real> copyOf(std::span<const real> values) {
  py::array_t<real> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

}  // namespace thyrix::python
