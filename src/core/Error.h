#pragma once
// The one exception type thrown at the edges (config, files, CLI, engine set-up). Its message is
// a single line that names the problem; the CLI prints it as "wiggle: <message>" and exits non-zero.
#include <stdexcept>
#include <string>

namespace wiggle {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace wiggle
