// The names of the pictures `ffcompat report` writes, relative to its output folder (report.cpp
// writes them, html.cpp shows them).
#pragma once
#include <cstddef>
#include <string>

namespace ffc::report {

std::string picture_path(const std::string& scene, int depth, const std::string& shading, bool error);
std::string ideal_path(const std::string& scene);
std::string regression_path(size_t index, const std::string& name, const std::string& what);  // what: mesa, diff

}  // namespace ffc::report
