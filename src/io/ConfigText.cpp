// The text of configuration values: numbers in shortest round-trip form, TOML quoting, a key's
// value as TOML or display text, and the words of range errors. Shared by io/Config*.cpp.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/ConfigKeys.h"

namespace wiggle::config_keys {

// Shortest text that reads back to the same double. Whole numbers below 1e15 are written without
// an exponent (2000000, not 2e+06) because people read them; they are exact either way.
std::string roundTripText(double v, bool tomlStyle) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::string s;
  if (v == std::floor(v) && std::fabs(v) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    s = buf;
    if (tomlStyle) s += ".0";  // a TOML float, so the file says the key is a real number
    return s;
  }
  // Shortest round-trip digits; fixed notation when it stays short (0.0001 reads better than
  // 1e-04), scientific otherwise (1e-08).
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  if (r.ec != std::errc() || r.ptr - buf > 9) r = std::to_chars(buf, buf + sizeof buf, v);
  s.assign(buf, r.ptr);
  // Large whole numbers may come out as plain digits (12003693070755665920), which TOML would
  // read as an out-of-range integer.
  if (tomlStyle && s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string quoteToml(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (u < 0x20 || u == 0x7f) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", u);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

namespace {

std::string listText(const std::vector<double>& v, bool tomlStyle) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ", ";
    out += roundTripText(v[i], tomlStyle);
  }
  return out + "]";
}

std::string pointsText(const Points& v, bool tomlStyle) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ", ";
    // Appended piece by piece: g++ 12 warns falsely (-Wrestrict) on "[" + std::string here.
    out += '[';
    out += roundTripText(v[i][0], tomlStyle);
    out += ", ";
    out += roundTripText(v[i][1], tomlStyle);
    out += ']';
  }
  return out + "]";
}

}  // namespace

// A key's value in `config`: TOML text (tomlStyle) or short display text.
std::string valueText(const KeyInfo& k, const RunConfig& config, bool tomlStyle) {
  RunConfig& c = mut(config);
  switch (k.kind) {
    case Kind::Number: return roundTripText(k.number(c), tomlStyle);
    case Kind::Integer: return std::to_string(k.integer(c));
    case Kind::Boolean: return k.boolean(c) ? "true" : "false";
    case Kind::Text: return tomlStyle ? quoteToml(k.text(c)) : k.text(c);
    case Kind::Choice: return tomlStyle ? quoteToml(chosen(k, config)) : chosen(k, config);
    case Kind::NumberList: return listText(k.numberList(c), tomlStyle);
    case Kind::PointList: return pointsText(k.pointList(c), tomlStyle);
  }
  return "";
}

// Any TOML value as text; strings are quoted when `quote` (always inside arrays and tables).
std::string nodeText(const toml::node& n, bool quote) {
  if (const auto* s = n.as_string()) return quote ? quoteToml(s->get()) : s->get();
  if (const auto* i = n.as_integer()) return std::to_string(i->get());
  if (const auto* f = n.as_floating_point()) return roundTripText(f->get(), false);
  if (const auto* b = n.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = n.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i) out += ", ";
      out += nodeText(*a->get(i), true);
    }
    return out + "]";
  }
  if (const auto* t = n.as_table()) {
    std::string out = "{";
    bool first = true;
    for (const auto& [key, value] : *t) {
      out += first ? " " : ", ";
      first = false;
      out += std::string(key.str()) + " = " + nodeText(value, true);
    }
    return out + (first ? "}" : " }");
  }
  std::ostringstream os;  // dates and times: toml++'s own form
  n.visit([&](const auto& v) { os << v; });
  return os.str();
}

std::string typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "floating-point number";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::array: return "array";
    case toml::node_type::table: return "table";
    default: return "date/time";
  }
}

std::string boundText(const Bound& lo, const Bound& hi) {
  std::string out;
  if (lo.present) out += (lo.inclusive ? ">= " : "> ") + roundTripText(lo.value, false);
  if (hi.present) {
    if (!out.empty()) out += " and ";
    out += (hi.inclusive ? "<= " : "< ") + roundTripText(hi.value, false);
  }
  return out;
}

// "" when v is finite and within the bounds, else what is wrong ("must be > 0").
std::string rangeProblem(double v, const Bound& lo, const Bound& hi) {
  if (!std::isfinite(v)) return "must be a finite number";
  const bool lowOk = !lo.present || (lo.inclusive ? v >= lo.value : v > lo.value);
  const bool highOk = !hi.present || (hi.inclusive ? v <= hi.value : v < hi.value);
  if (lowOk && highOk) return "";
  return "must be " + boundText(lo, hi);
}

}  // namespace wiggle::config_keys
