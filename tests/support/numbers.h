// Constants the tests share, declared once so that test files compiled in one batch
// (cmake/CollidoUnity.cmake) do not each define their own.
#pragma once

namespace collido::test {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace collido::test
