#pragma once
// Reading a decimal number from text, the one way every reader in the core does it (issue 41).
// std::from_chars for double where the standard library has it (libstdc++ on the desktop); the
// same grammar read through strtod where it has not (emscripten's libc++ 14, the WebAssembly
// build). So the desktop and the browser read every number of a program and a setup file alike.
//
//   double v = 0;
//   readDouble("12.5E-1X", ..., v)  -> v = 1.25, ptr at 'X'
//   readDouble("+3", ..., v)        -> invalid_argument (as from_chars: no leading '+' or blank)
#include <charconv>

namespace klueng::core {

// As std::from_chars(first, last, value) with chars_format::general: [-]digits[.digits][(e|E)[+|-]digits],
// [-].digits..., also inf, infinity, nan and nan(chars), letters in either case. `value` is set only when
// ec is errc{}; a number too large or too small for a double is result_out_of_range.
std::from_chars_result readDouble(const char* first, const char* last, double& value);

namespace detail {
// The strtod reading (what a library without a floating-point from_chars uses); public for the test
// that holds it to std::from_chars on the desktop.
std::from_chars_result readDoubleByStrtod(const char* first, const char* last, double& value);
}  // namespace detail

}  // namespace klueng::core
