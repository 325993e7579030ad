// A test process's own temporary folder: made once (mkdtemp, so runs side by side never share a
// file), removed with everything in it when the tests end. Tests write nowhere else.
#pragma once
#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace ffc::test {

inline std::filesystem::path temp_path(const std::string& name) {
  struct Dir {
    std::filesystem::path path;
    pid_t owner = getpid();  // a forked child (a death test) must not remove its parent's folder
    Dir() {
      std::string t = (std::filesystem::temp_directory_path() / "ffcompat_test.XXXXXX").string();
      if (!mkdtemp(t.data())) throw std::runtime_error("mkdtemp failed in " + t);
      path = t;
    }
    ~Dir() {
      if (getpid() != owner) return;
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir d;
  return d.path / name;
}

}  // namespace ffc::test
