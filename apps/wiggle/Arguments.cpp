#include "Arguments.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/Error.h"

namespace wiggle::cli {

double parseNumber(const std::string& text, const std::string& what) {
  const char* begin = text.c_str();
  while (*begin == ' ') ++begin;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  while (end && *end == ' ') ++end;
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(value))
    throw Error(what + ": '" + text + "' is not a number");
  return value;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

}  // namespace wiggle::cli
