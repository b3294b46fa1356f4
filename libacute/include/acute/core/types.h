// Layer: core. Basic value types shared by every layer; includes Eigen only.
#pragma once

#include <Eigen/Core>

namespace acute {

/// A point or vector of the plane.
using Point2 = Eigen::Vector2d;

/// Sign of a determinant, decided exactly by the predicates.
enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

/// Exact classification of an angle (sign of the dot product at its apex).
enum class AngleKind : int { Acute, Right, Obtuse };

inline Sign sign_of(double x) { return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero); }
inline Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }

}  // namespace acute
