// A run's records: the exact state text, the CSV log, the fitness plot, the progress line and
// files replaced atomically.

#include <Evolution/AtomicFile.h>
#include <Evolution/FitnessHistory.h>
#include <Evolution/FitnessPlot.h>
#include <Evolution/ProgressLine.h>
#include <Evolution/StateText.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace thyrix {
namespace {

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(StateTextTest, DoublesRoundTripBitForBit) {
  const std::vector<double> values = {0.1,   -1.0 / 3, std::numeric_limits<double>::denorm_min(),
                                      1e308, -0.0,     std::numeric_limits<double>::max()};
  std::stringstream text;
  StateWriter writer(text);
  writer.integer("count", 18446744073709551615ull);
  writer.word("kind", "test");
  writer.doubles("values", values);
  StateReader reader(text, "test state");
  EXPECT_EQ(reader.integer("count"), 18446744073709551615ull);
  EXPECT_EQ(reader.word("kind"), "test");
  const std::vector<double> back = reader.doubles("values", values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[i]), std::bit_cast<std::uint64_t>(values[i]));
  EXPECT_NO_THROW(reader.end());
}

TEST(StateTextTest, MismatchesSayWhereAndWhat) {
  const auto message = [](const std::string& text, auto read) {
    std::stringstream in(text);
    StateReader reader(in, "my file");
    try {
      read(reader);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("a 1\nb 2\n",
                    [](StateReader& r) {
                      (void)r.integer("a");
                      (void)r.integer("c");
                    }),
            "my file, line 2: expected 'c', found 'b'");
  EXPECT_EQ(message("a 1\n", [](StateReader& r) { (void)r.doubles("a", 2); }),
            "my file, line 1: expected 'a 2 ...', found 'a 1'");
  EXPECT_EQ(message("a 2 1p+0\n", [](StateReader& r) { (void)r.doubles("a", 2); }),
            "my file, line 1: 'a' needs 2 values, found 1");
  EXPECT_EQ(message("a -1\n", [](StateReader& r) { (void)r.integer("a"); }).substr(0, 30),
            "my file, line 1: 'a' needs a w");
  EXPECT_EQ(message("", [](StateReader& r) { (void)r.word("a"); }),
            "my file, line 1: ends early: expected 'a' (truncated file?)");
  EXPECT_EQ(message("x\n", [](StateReader& r) { r.end(); }),
            "my file, line 1: unexpected text after the end: 'x'");
}

TEST(FitnessHistoryTest, CsvHasAHeaderAndOneExactRowPerGeneration) {
  const std::vector<GenerationRecord> records = {{1, 0.5, 0.25, 0.5}, {2, 0.1, -3, 0.5}};
  EXPECT_EQ(fitnessCsv(records),
            "generation,best,mean,best_so_far\n1,0.5,0.25,0.5\n2,0.1,-3,0.5\n");
}

TEST(FitnessPlotTest, DrawsBothSeriesAtTheirPixels) {
  // Generations 1..3 span the plot's 540 pixels from x = 80; fitness 0..10 its 310 from y = 350.
  const std::vector<GenerationRecord> records = {{1, 0, 0, 0}, {2, 5, 2, 5}, {3, 10, 4, 10}};
  const std::string svg = fitnessPlotSvg(records, "a <title>");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<polyline class=\"best\" points=\"80,350 350,195 620,40\""),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<polyline class=\"mean\" points=\"80,350 350,288 620,226\""),
            std::string::npos);
  EXPECT_NE(svg.find(">a &lt;title&gt;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">generation</text>"), std::string::npos);
  EXPECT_NE(svg.find(">fitness</text>"), std::string::npos);
  EXPECT_NE(svg.find(">10</text>"), std::string::npos);  // a tick at the top
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_NE(fitnessPlotSvg({}, "empty").find("</svg>"), std::string::npos);
}

TEST(ProgressLineTest, ShowsEveryFieldAndRedrawsOnlyOnATerminal) {
  Progress p;
  p.generation = 12;
  p.generations = 100;
  p.best = 3.25;
  p.mean = 1.07;
  p.bestSoFar = 3.5;
  p.evaluationsPerSecond = 812.4;
  p.secondsLeft = 61;
  EXPECT_EQ(progressText(p),
            "gen 12/100  best 3.25  mean 1.07  best so far 3.5  812 evals/s  left 1:01");
  const auto shown = [&](bool terminal) {
    std::FILE* file = std::tmpfile();
    {
      ProgressLine line(file, terminal);
      line.update(p);
      line.update(p);
    }
    std::rewind(file);
    std::string text;
    for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
    std::fclose(file);
    return text;
  };
  const std::string line = progressText(p);
  EXPECT_EQ(shown(false), line + "\n" + line + "\n");
  EXPECT_EQ(shown(true), "\r" + line + "\x1b[K\r" + line + "\x1b[K\n");
}

TEST(AtomicFileTest, ReplacesWholeOrLeavesTheOldFile) {
  const auto dir = std::filesystem::temp_directory_path() / "thyrix_atomic_file_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "a.txt";
  writeFileAtomically(path, "first");
  writeFileAtomically(path, "second");
  EXPECT_EQ(readFile(path), "second");
  EXPECT_FALSE(std::filesystem::exists(dir / "a.txt.tmp"));
  // A directory where the file should go cannot be replaced: the old one stays.
  std::filesystem::create_directories(dir / "b.txt");
  EXPECT_THROW(writeFileAtomically(dir / "b.txt", "x"), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "b.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b.txt.tmp"));
  EXPECT_THROW(writeFileAtomically(dir / "missing" / "c.txt", "x"), std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace thyrix
