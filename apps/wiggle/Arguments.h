#pragma once
// The text of option values that CLI11 hands over as strings (lists, ranges, pairs): split and read
// one way for every command, each error one line naming the option.
#include <string>
#include <vector>

namespace wiggle::cli {

// A finite decimal number (blanks around it allowed); throws wiggle::Error "WHAT: 'TEXT' is not a number".
double parseNumber(const std::string& text, const std::string& what);

// TEXT cut at every SEP ("a,b," -> "a", "b", ""); "" -> nothing.
std::vector<std::string> split(const std::string& text, char sep);

}  // namespace wiggle::cli
