// Runs a probe program and compares two probes' outputs line for line, naming the first line
// where they part (with a little context) rather than dumping megabytes.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace ffc::test {

struct ProbeOutput {
  int status = -1;
  std::vector<std::string> lines;
};

inline ProbeOutput run_probe(const std::string &command) {
  ProbeOutput out;
  FILE *pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  std::string line;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) {
    line += buffer;
    if (!line.empty() && line.back() == '\n') {
      line.pop_back();
      out.lines.push_back(line);
      line.clear();
    }
  }
  if (!line.empty()) out.lines.push_back(line);
  const int status = pclose(pipe);
  out.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

inline size_t count_prefix(const std::vector<std::string> &lines, const std::string &prefix) {
  size_t n = 0;
  for (const std::string &line : lines) n += line.compare(0, prefix.size(), prefix) == 0;
  return n;
}

// The nearest "#" line at or above `index`: what the probe was drawing there.
inline std::string section_of(const std::vector<std::string> &lines, size_t index) {
  std::string section;
  for (size_t i = 0; i <= index && i < lines.size(); ++i)
    if (!lines[i].empty() && lines[i][0] == '#') section = lines[i];
  return section;
}

inline ::testing::AssertionResult same_lines(const char *expected_expr, const char *actual_expr,
                                             const std::vector<std::string> &expected,
                                             const std::vector<std::string> &actual) {
  const size_t common = std::min(expected.size(), actual.size());
  for (size_t i = 0; i < common; ++i)
    if (expected[i] != actual[i])
      return ::testing::AssertionFailure()
             << expected_expr << " and " << actual_expr << " part at line " << i + 1 << " (in \""
             << section_of(expected, i) << "\"):\n  expected: " << expected[i] << "\n  actual:   " << actual[i];
  if (expected.size() != actual.size())
    return ::testing::AssertionFailure() << expected_expr << " has " << expected.size() << " lines, " << actual_expr
                                         << " has " << actual.size();
  return ::testing::AssertionSuccess();
}

}  // namespace ffc::test
