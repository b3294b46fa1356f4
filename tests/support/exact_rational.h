// Test-only exact oracle. Every finite double is an integer times a power of two, and so is every
// sum, difference and product of such numbers: a Dyadic holds mantissa * 2^exponent with an
// arbitrary-precision signed integer mantissa. Small and slow on purpose; independent of the
// expansion arithmetic it checks.
#pragma once

#include <acute/core/types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace acute::test {

/// Sign-magnitude big integer on 32-bit limbs (little-endian, no leading zero limbs).
class BigInt {
 public:
  BigInt() = default;
  static BigInt from_u64(std::uint64_t v, bool negative) {
    BigInt r;
    while (v != 0) {
      r.mag_.push_back(static_cast<std::uint32_t>(v));
      v >>= 32;
    }
    r.neg_ = negative && !r.mag_.empty();
    return r;
  }

  int sign() const { return mag_.empty() ? 0 : (neg_ ? -1 : 1); }

  BigInt shifted_left(int bits) const {
    if (mag_.empty() || bits == 0) return *this;
    BigInt r;
    r.neg_ = neg_;
    const int limbs = bits / 32, rem = bits % 32;
    r.mag_.assign(static_cast<std::size_t>(limbs), 0);
    std::uint32_t carry = 0;
    for (std::uint32_t limb : mag_) {
      r.mag_.push_back(static_cast<std::uint32_t>((std::uint64_t{limb} << rem) | carry));
      carry = rem == 0 ? 0 : limb >> (32 - rem);
    }
    if (carry != 0) r.mag_.push_back(carry);
    return r;
  }

  friend BigInt operator-(BigInt x) {
    x.neg_ = !x.neg_ && !x.mag_.empty();
    return x;
  }
  friend BigInt operator+(const BigInt& x, const BigInt& y) {
    if (x.neg_ == y.neg_) return make(add_mag(x.mag_, y.mag_), x.neg_);
    const int c = cmp_mag(x.mag_, y.mag_);
    if (c == 0) return BigInt();
    return c > 0 ? make(sub_mag(x.mag_, y.mag_), x.neg_) : make(sub_mag(y.mag_, x.mag_), y.neg_);
  }
  friend BigInt operator-(const BigInt& x, const BigInt& y) { return x + (-y); }
  friend BigInt operator*(const BigInt& x, const BigInt& y) {
    if (x.mag_.empty() || y.mag_.empty()) return BigInt();
    std::vector<std::uint32_t> r(x.mag_.size() + y.mag_.size(), 0);
    for (std::size_t i = 0; i < x.mag_.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < y.mag_.size(); ++j) {
        const std::uint64_t t = std::uint64_t{x.mag_[i]} * y.mag_[j] + r[i + j] + carry;
        r[i + j] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
      r[i + y.mag_.size()] = static_cast<std::uint32_t>(carry);
    }
    return make(std::move(r), x.neg_ != y.neg_);
  }

 private:
  using Mag = std::vector<std::uint32_t>;
  static BigInt make(Mag m, bool negative) {
    while (!m.empty() && m.back() == 0) m.pop_back();
    BigInt r;
    r.mag_ = std::move(m);
    r.neg_ = negative && !r.mag_.empty();
    return r;
  }
  static int cmp_mag(const Mag& x, const Mag& y) {
    if (x.size() != y.size()) return x.size() < y.size() ? -1 : 1;
    for (std::size_t i = x.size(); i-- > 0;)
      if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
  }
  static Mag add_mag(const Mag& x, const Mag& y) {
    Mag r(std::max(x.size(), y.size()) + 1, 0);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i + 1 < r.size(); ++i) {
      const std::uint64_t t = (i < x.size() ? x[i] : 0) + std::uint64_t{i < y.size() ? y[i] : 0} + carry;
      r[i] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    r.back() = static_cast<std::uint32_t>(carry);
    return r;
  }
  static Mag sub_mag(const Mag& x, const Mag& y) {  // |x| >= |y|
    Mag r(x.size(), 0);
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      std::int64_t t = std::int64_t{x[i]} - (i < y.size() ? std::int64_t{y[i]} : 0) - borrow;
      borrow = t < 0 ? 1 : 0;
      if (t < 0) t += std::int64_t{1} << 32;
      r[i] = static_cast<std::uint32_t>(t);
    }
    return r;
  }

  bool neg_ = false;
  Mag mag_;
};

/// mantissa * 2^exponent, exact.
class Dyadic {
 public:
  Dyadic() = default;
  explicit Dyadic(double x) {  // x finite
    if (x == 0) return;
    int e = 0;
    const double f = std::frexp(std::fabs(x), &e);  // |x| = f * 2^e, f in [0.5, 1)
    const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // exact: 53 bits
    mant_ = BigInt::from_u64(m, x < 0);
    exp_ = e - 53;
  }
  int sign() const { return mant_.sign(); }

  friend Dyadic operator+(const Dyadic& x, const Dyadic& y) {
    if (x.sign() == 0) return y;
    if (y.sign() == 0) return x;
    const int e = std::min(x.exp_, y.exp_);
    Dyadic r;
    r.mant_ = x.mant_.shifted_left(x.exp_ - e) + y.mant_.shifted_left(y.exp_ - e);
    r.exp_ = e;
    return r;
  }
  friend Dyadic operator-(const Dyadic& x) {
    Dyadic r = x;
    r.mant_ = -r.mant_;
    return r;
  }
  friend Dyadic operator-(const Dyadic& x, const Dyadic& y) { return x + (-y); }
  friend Dyadic operator*(const Dyadic& x, const Dyadic& y) {
    Dyadic r;
    r.mant_ = x.mant_ * y.mant_;
    r.exp_ = x.exp_ + y.exp_;
    return r;
  }

 private:
  BigInt mant_;
  int exp_ = 0;
};

inline Sign to_sign(int s) { return static_cast<Sign>(s); }

/// Oracle: sign of det[b - a, c - a].
inline Sign oracle_orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const Dyadic ax(a.x()), ay(a.y()), bx(b.x()), by(b.y()), cx(c.x()), cy(c.y());
  return to_sign(((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)).sign());
}

/// Oracle: sign of the 3x3 lifted incircle determinant (Positive: d inside ccw abc).
inline Sign oracle_incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Dyadic dx(d.x()), dy(d.y());
  const Dyadic adx = Dyadic(a.x()) - dx, ady = Dyadic(a.y()) - dy;
  const Dyadic bdx = Dyadic(b.x()) - dx, bdy = Dyadic(b.y()) - dy;
  const Dyadic cdx = Dyadic(c.x()) - dx, cdy = Dyadic(c.y()) - dy;
  const Dyadic alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const Dyadic det = alift * (bdx * cdy - cdx * bdy) - blift * (adx * cdy - cdx * ady) + clift * (adx * bdy - bdx * ady);
  return to_sign(det.sign());
}

/// Oracle: sign of (p - apex) . (q - apex).
inline Sign oracle_dot(const Point2& apex, const Point2& p, const Point2& q) {
  const Dyadic ox(apex.x()), oy(apex.y());
  return to_sign(((Dyadic(p.x()) - ox) * (Dyadic(q.x()) - ox) + (Dyadic(p.y()) - oy) * (Dyadic(q.y()) - oy)).sign());
}

}  // namespace acute::test
