// Golden perception text shared by the perception and session tests.
#pragma once

namespace turf::simspark::test {

// A type 0 Nao's arm and leg joints at 0 degrees, in the order a perception
// lists them (after the head joints and See).
inline constexpr char kLimbJointsAtZero[] =
    "(HJ (n raj1) (ax 0.00))(HJ (n raj2) (ax 0.00))(HJ (n raj3) (ax 0.00))(HJ (n raj4) (ax 0.00))"
    "(HJ (n laj1) (ax 0.00))(HJ (n laj2) (ax 0.00))(HJ (n laj3) (ax 0.00))(HJ (n laj4) (ax 0.00))"
    "(HJ (n rlj1) (ax 0.00))(HJ (n rlj2) (ax 0.00))(HJ (n rlj3) (ax 0.00))(HJ (n rlj4) (ax 0.00))"
    "(HJ (n rlj5) (ax 0.00))(HJ (n rlj6) (ax 0.00))"
    "(HJ (n llj1) (ax 0.00))(HJ (n llj2) (ax 0.00))(HJ (n llj3) (ax 0.00))(HJ (n llj4) (ax 0.00))"
    "(HJ (n llj5) (ax 0.00))(HJ (n llj6) (ax 0.00))";

}  // namespace turf::simspark::test
