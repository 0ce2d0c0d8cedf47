#pragma once
/// @file Genome.h
/// @brief A network's shape and parameters, written to and read from a versioned text file.

#include <Controller/NeuralController.h>
#include <Controller/NeuralNetwork.h>

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace thyrix {

/// Everything needed to rebuild a NeuralController: the network's shape, then its parameters.
///
/// The text form, one item a line (the parameters are C hexadecimal floats, so a round trip is
/// exact; decimal numbers are read too):
///
///     thyrix-genome 1
///     kind feed-forward          (or ctrnn)
///     activation tanh            (or logistic)
///     layers 35 8 5
///     parameters 333
///     0x1.8p-1
///     ...                        (one parameter a line, in NetworkSpec's order)
struct Genome {
  /// The version written in the first line; read() refuses any other.
  static constexpr int version = 1;

  NetworkSpec spec;              ///< the network the parameters are for
  std::vector<real> parameters;  ///< spec.parameterCount() values, in NetworkSpec's order

  /// Writes the text form.
  /// @throws InvalidArgument naming a "NetworkSpec." field (invalid spec) or
  ///         "Genome.parameters" (not spec.parameterCount() values, or one not finite)
  void write(std::ostream& out) const;

  /// Reads the text form, exactly as write() wrote it.
  /// @throws std::runtime_error saying which line is wrong and why: not a genome, another
  ///         version, an unknown kind or activation, bad layer sizes, a parameter count that is
  ///         not the spec's, a missing, unreadable or non-finite parameter, or text after the
  ///         last parameter
  static Genome read(std::istream& in);

  /// Reads the file at @p path (read()), its name heading any error.
  /// @throws std::runtime_error when the file cannot be opened or read() refuses it
  static Genome load(const std::string& path);

  /// Throws unless the network reads @p sensors inputs and writes @p effectors outputs, e.g. the
  /// counts of the agent it is to drive.
  /// @throws std::runtime_error saying both counts
  void requireShape(std::size_t sensors, std::size_t effectors) const;

  /// A controller running this network with these parameters.
  /// @param timestep the Ctrnn's Euler step (s), normally the simulator's
  /// @throws InvalidArgument as NeuralController's constructor and setParameters()
  [[nodiscard]] std::unique_ptr<NeuralController> makeController(real timestep = real(0.01)) const;
};

}  // namespace thyrix
