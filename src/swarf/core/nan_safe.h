// nan_safe.h: formatting a number that may be NaN without raising a floating-point exception.
//
// fmt's formatting of a double with a precision ("{:.3g}") compares the value with itself, an
// ordered comparison that raises FE_INVALID on a NaN: with the floating-point traps of the test
// build (app/fp_traps.h) a table or message that names an unavailable number ends in SIGFPE.
// A signalling NaN (which an HDF5 file can hold: a lattice file's radius, found by the lattice
// fuzzer) raises FE_INVALID in fmt even without a precision, and so does std::isnan (an
// unordered comparison signals on it). nan_safe(x) writes "nan" itself after a test of the bits,
// which raises nothing, and hands fmt only the other values, with the format spec as given:
// fmt::format("{:.3g}", nan_safe(x)). Every message that names a value read from a file which
// may be NaN prints it through nan_safe.
#pragma once

#include <fmt/format.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>

namespace swarf {

/// A double that fmt formats as "nan" when it is NaN, else as the double.
struct NanSafe {
  double value;
};
inline NanSafe nan_safe(double v) { return {v}; }

}  // namespace swarf

template <>
struct fmt::formatter<swarf::NanSafe> : fmt::formatter<double> {
  // The spec's fill, alignment and width ("<", ">10" of ">10.4g") for "nan", so that a table's
  // column stays aligned; the rest (precision, type) is the double's.
  char text_spec_[16] = {};

  template <class ParseContext>
  constexpr auto parse(ParseContext& ctx) -> decltype(ctx.begin()) {
    std::size_t n = 0;
    for (auto it = ctx.begin(); it != ctx.end() && *it != '}' && *it != '.' && n + 1 < sizeof text_spec_; ++it) {
      const char c = *it;
      if (c >= 'a' && c <= 'z') break;  // (the type: e, f, g)
      text_spec_[n++] = c;
    }
    return fmt::formatter<double>::parse(ctx);
  }

  template <class Context>
  auto format(swarf::NanSafe n, Context& ctx) const -> decltype(ctx.out()) {
    if ((std::bit_cast<std::uint64_t>(n.value) & 0x7fffffffffffffffull) > 0x7ff0000000000000ull)  // (NaN)
      return fmt::format_to(ctx.out(), fmt::runtime(std::string("{:") + text_spec_ + "}"), "nan");
    return fmt::formatter<double>::format(n.value, ctx);
  }
};
