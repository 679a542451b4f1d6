#pragma once
// Mathematical constants shared by every module (the one definition of pi).

namespace wear {

/// [-] The ratio of a circle's circumference to its diameter (the double nearest it).
inline constexpr double pi = 3.14159265358979323846;

} // namespace wear
