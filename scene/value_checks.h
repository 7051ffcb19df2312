// Checks of the values a user gives a part or a scene (a script's
// parameters, or the library's), with the messages both get: "material:
// ambient must be in [0, 1]" names the function and the parameter as the
// script spells them. Each throws std::invalid_argument. A script's numbers
// are finite already; the library's may not be, and a NaN or an infinity is
// refused as the script refuses one: "point_light: pos must be finite".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "engine/ray.h"

namespace csgray::detail {

// Finite: no NaN or infinity.
void checkFinite(const std::string& function, const char* key, double value);
void checkFinite(const std::string& function, const char* key, const dvec3& vector);
// In [0, 1].
void checkUnit(const std::string& function, const char* key, double value);
// > 0.
void checkPositive(const std::string& function, const char* key, double value);
// >= 0.
void checkNonNegative(const std::string& function, const char* key, double value);
// A colour: every component >= 0.
void checkColor(const std::string& function, const char* key, const dvec3& color);
// Not the zero vector.
void checkNonZero(const std::string& function, const char* key, const dvec3& vector);
// The edit distance between two names (Levenshtein 1966: insertions,
// deletions and substitutions), for the "did you mean" of a message.
std::size_t editDistance(std::string_view a, std::string_view b);
// A whole number from lo to hi, returned as an int.
int checkWhole(const std::string& function, const char* key, double value, int lo, int hi);

// A value a user gave, as a message shows it: at most 60 characters (or
// `length`), the middle of a longer one left out ("..."), so that a value
// of 100 000 characters does not fill the screen while a long path keeps
// its start and its file name; a NUL byte shown as '?'.
std::string shownValue(std::string_view text, std::size_t length = 60);

}  // namespace csgray::detail
