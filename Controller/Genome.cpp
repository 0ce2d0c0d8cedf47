#include <Controller/Genome.h>
#include <ThyrixLite/InvalidArgument.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace thyrix {

namespace {

constexpr const char* magic = "thyrix-genome";

// Reads the lines of a genome, numbering them for the messages.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}

  // The next line, split into words; throws at the end of the input.
  std::vector<std::string> words(const char* expected) {
    std::string line;
    if (!std::getline(in_, line)) fail(++number_, std::string("missing: expected ") + expected);
    ++number_;
    std::istringstream stream(line);
    std::vector<std::string> result;
    for (std::string word; stream >> word;) result.push_back(word);
    return result;
  }

  // True when nothing but white space is left.
  bool atEnd() {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return false;
    }
    return true;
  }

  [[noreturn]] static void fail(std::size_t line, const std::string& problem) {
    throw std::runtime_error("genome line " + std::to_string(line) + ": " + problem);
  }
  [[noreturn]] void fail(const std::string& problem) const { fail(number_, problem); }

  // The words of a line that must read `key value...`, without the key.
  std::vector<std::string> keyed(const char* key, const char* expected) {
    std::vector<std::string> result = words(expected);
    if (result.empty() || result.front() != key)
      fail(std::string("expected '") + key + " " + expected + "'");
    result.erase(result.begin());
    return result;
  }

 private:
  std::istream& in_;
  std::size_t number_ = 0;
};

// A whole word as an unsigned count, or nothing.
bool parseCount(const std::string& word, std::size_t& value) {
  if (word.empty() || word.size() > 18 || word.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = static_cast<std::size_t>(std::stoull(word));
  return true;
}

// A whole word as a finite real (hexadecimal or decimal), or nothing.
bool parseReal(const std::string& word, real& value) {
  const char* begin = word.c_str();
  char* end = nullptr;
  const double parsed = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(parsed)) return false;
  if (std::abs(parsed) > static_cast<double>(std::numeric_limits<real>::max())) return false;
  value = static_cast<real>(parsed);
  return true;
}

}  // namespace

void Genome::write(std::ostream& out) const {
  const std::size_t count = spec.parameterCount();  // validates the spec
  if (parameters.size() != count)
    throw InvalidArgument("Genome.parameters", "must have " + std::to_string(count) +
                                                   " values (got " +
                                                   std::to_string(parameters.size()) + ")");
  for (std::size_t p = 0; p < count; ++p)
    if (!std::isfinite(parameters[p]))
      throw InvalidArgument("Genome.parameters", "value " + std::to_string(p) + " must be finite");
  out << magic << ' ' << version << '\n'
      << "kind " << toString(spec.kind) << '\n'
      << "activation " << toString(spec.activation) << '\n'
      << "layers";
  for (const std::size_t size : spec.layers) out << ' ' << size;
  out << '\n' << "parameters " << count << '\n';
  char buffer[64];
  for (const real value : parameters) {
    std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(value));
    out << buffer << '\n';
  }
}

Genome Genome::read(std::istream& in) {
  LineReader reader(in);
  Genome genome;

  const std::vector<std::string> header = reader.words("'thyrix-genome 1'");
  if (header.size() != 2 || header[0] != magic)
    reader.fail("not a Thyrix genome (the first line must be 'thyrix-genome " +
                std::to_string(version) + "')");
  if (header[1] != std::to_string(version))
    reader.fail("version " + header[1] + " is not supported (this reader knows version " +
                std::to_string(version) + ")");

  const std::vector<std::string> kind = reader.keyed("kind", "feed-forward|ctrnn");
  if (kind.size() == 1 && kind[0] == toString(NetworkKind::FeedForward))
    genome.spec.kind = NetworkKind::FeedForward;
  else if (kind.size() == 1 && kind[0] == toString(NetworkKind::Ctrnn))
    genome.spec.kind = NetworkKind::Ctrnn;
  else
    reader.fail("unknown kind (expected 'feed-forward' or 'ctrnn')");

  const std::vector<std::string> activation = reader.keyed("activation", "tanh|logistic");
  if (activation.size() == 1 && activation[0] == toString(Activation::Tanh))
    genome.spec.activation = Activation::Tanh;
  else if (activation.size() == 1 && activation[0] == toString(Activation::Logistic))
    genome.spec.activation = Activation::Logistic;
  else
    reader.fail("unknown activation (expected 'tanh' or 'logistic')");

  const std::vector<std::string> layers = reader.keyed("layers", "SIZE SIZE...");
  for (const std::string& word : layers) {
    std::size_t size = 0;
    if (!parseCount(word, size)) reader.fail("layer size '" + word + "' is not a count");
    genome.spec.layers.push_back(size);
  }
  std::size_t expected = 0;
  try {
    expected = genome.spec.parameterCount();
  } catch (const InvalidArgument& error) {
    reader.fail(error.what());
  }

  const std::vector<std::string> count = reader.keyed("parameters", "COUNT");
  std::size_t declared = 0;
  if (count.size() != 1 || !parseCount(count[0], declared))
    reader.fail("expected 'parameters COUNT'");
  if (declared != expected)
    reader.fail("declares " + std::to_string(declared) + " parameters, but a " +
                std::string(toString(genome.spec.kind)) + " network of these layers has " +
                std::to_string(expected));

  genome.parameters.reserve(expected);
  for (std::size_t p = 0; p < expected; ++p) {
    const std::vector<std::string> words = reader.words(
        ("parameter " + std::to_string(p) + " of " + std::to_string(expected)).c_str());
    real value = 0;
    if (words.size() != 1 || !parseReal(words[0], value))
      reader.fail("parameter " + std::to_string(p) + " is not one finite number");
    genome.parameters.push_back(value);
  }
  if (!reader.atEnd()) reader.fail("unexpected text after the last parameter");
  return genome;
}

Genome Genome::load(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot be opened");
  try {
    return read(file);
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
}

void Genome::requireShape(std::size_t sensors, std::size_t effectors) const {
  const std::size_t inputs = spec.inputCount();
  const std::size_t outputs = spec.outputCount();
  if (inputs != sensors || outputs != effectors)
    throw std::runtime_error("the genome's network has " + std::to_string(inputs) + " inputs and " +
                             std::to_string(outputs) + " outputs, but the agent has " +
                             std::to_string(sensors) + " sensors and " + std::to_string(effectors) +
                             " effectors");
}

std::unique_ptr<NeuralController> Genome::makeController(real timestep) const {
  auto controller = std::make_unique<NeuralController>(spec, timestep);
  controller->setParameters(parameters);
  return controller;
}

}  // namespace thyrix
