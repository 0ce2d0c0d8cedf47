#include <GUIWx/GuiOptions.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace thyrix {

const char* const guiOptionsUsage =
    "  --steps N            pause after N steps (default: run until closed)\n"
    "  --speed S            steps per second, or 'max' (default 100)\n"
    "  --paused             start paused\n"
    "  --geometry WxH[+X+Y] window size and position in pixels (default 1000x700)\n"
    "  --screenshot FILE    save a PNG of the view after --after steps, then exit\n"
    "  --after N            steps before the screenshot (default 100; as fast as possible\n"
    "                       unless --speed is given)\n"
    "  --print-drag         print the view's mapping, each object's screen pixel and every\n"
    "                       drag event (start, move, end, and the position 10 and 50 steps\n"
    "                       after release) to stdout\n";

namespace {

std::invalid_argument bad(std::string_view option, std::string_view expected,
                          std::string_view value) {
  return std::invalid_argument(std::string(option) + " needs " + std::string(expected) + ", not '" +
                               std::string(value) + "'");
}

// A whole number at the front of @p text, at least @p low; advances @p text past it.
template <class T>
bool leadingNumber(std::string_view& text, T low, T& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || value < low) return false;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return true;
}

template <class T>
T wholeNumber(std::string_view option, std::string_view text, T low) {
  std::string_view rest = text;
  T value{};
  if (!leadingNumber(rest, low, value) || !rest.empty())
    throw bad(option, "a whole number >= " + std::to_string(low), text);
  return value;
}

}  // namespace

int parseGuiOption(int argc, char** argv, int i, GuiOptions& options) {
  const std::string_view option = argv[i];
  if (option == "--print-drag") {
    options.printDrag = true;
    return 1;
  }
  if (option == "--paused") {
    options.paused = true;
    return 1;
  }
  const bool takesValue = option == "--steps" || option == "--speed" || option == "--geometry" ||
                          option == "--screenshot" || option == "--after";
  if (!takesValue) return 0;
  if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
  const std::string_view value = argv[i + 1];
  if (option == "--steps") {
    options.stopAfter = wholeNumber<std::uint64_t>(option, value, 0);
  } else if (option == "--after") {
    options.screenshotAfter = wholeNumber<std::uint64_t>(option, value, 0);
  } else if (option == "--screenshot") {
    if (value.empty()) throw bad(option, "a file name", value);
    options.screenshot = value;
  } else if (option == "--speed") {
    if (value == "max") {
      options.stepsPerSecond = 0;
    } else {
      double speed = 0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), speed);
      if (error != std::errc() || end != value.data() + value.size() || !(speed > 0) ||
          !std::isfinite(speed))
        throw bad(option, "a positive number of steps per second or 'max'", value);
      options.stepsPerSecond = speed;
    }
  } else {  // --geometry WxH[+X+Y]
    std::string_view rest = value;
    int width = 0;
    int height = 0;
    int x = -1;
    int y = -1;
    bool ok = leadingNumber(rest, 1, width) && rest.starts_with('x');
    if (ok) {
      rest.remove_prefix(1);
      ok = leadingNumber(rest, 1, height);
    }
    if (ok && !rest.empty()) {
      ok = rest.starts_with('+');
      if (ok) rest.remove_prefix(1);
      ok = ok && leadingNumber(rest, 0, x) && rest.starts_with('+');
      if (ok) rest.remove_prefix(1);
      ok = ok && leadingNumber(rest, 0, y) && rest.empty();
    }
    if (!ok || width > 100000 || height > 100000)
      throw bad(option, "WIDTHxHEIGHT or WIDTHxHEIGHT+X+Y in pixels", value);
    options.width = width;
    options.height = height;
    options.x = x;
    options.y = y;
  }
  return 2;
}

}  // namespace thyrix
