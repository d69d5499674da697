// Number formatting for the mesh writers. Owner of text_writer.h.

#include "text_writer.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace subdivlab::detail {
namespace {

/// The 17 significant digits of x > 0 as printf's "%.17g" rounds them
/// (exactly, ties to even): x ~ d * 10^(e10 - 16) with 10^16 <= d < 10^17.
/// Exact 128-bit arithmetic covers [1e-5, 1e17), where mesh coordinates
/// live; false outside it (the caller then asks snprintf). printf itself
/// costs about ten times as much per number, and em++ 3.1.6's libc++ has no
/// floating-point std::to_chars.
bool decimal_digits_17(double x, std::uint64_t& d, int& e10) {
  if (!(x >= 1e-5 && x < 1e17)) return false;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>(bits >> 52);  // x >= 1e-5: normal
  const std::uint64_t f = (bits & ((1ull << 52) - 1)) | (1ull << 52);
  const int e2 = biased - 1075;  // x = f * 2^e2
  static const std::uint64_t pow5[] = {1ull,
                                       5ull,
                                       25ull,
                                       125ull,
                                       625ull,
                                       3125ull,
                                       15625ull,
                                       78125ull,
                                       390625ull,
                                       1953125ull,
                                       9765625ull,
                                       48828125ull,
                                       244140625ull,
                                       1220703125ull,
                                       6103515625ull,
                                       30517578125ull,
                                       152587890625ull,
                                       762939453125ull,
                                       3814697265625ull,
                                       19073486328125ull,
                                       95367431640625ull,
                                       476837158203125ull,
                                       2384185791015625ull};
  constexpr std::uint64_t ten16 = 10000000000000000ull;
  // floor(log10(x)) from the binary exponent (log10(2) ~ 78913 / 2^18),
  // corrected by the loop when it is one off.
  int e = ((biased - 1023) * 78913) >> 18;
  for (int tries = 0; tries < 4; ++tries) {
    const int k = 16 - e;  // y = x * 10^k = f * 5^k * 2^(e2 + k)
    if (k < 0 || k > 22) return false;
    const unsigned __int128 m = static_cast<unsigned __int128>(f) * pow5[k];
    const int s = e2 + k;
    std::uint64_t q = 0;
    bool half = false, above = false;  // the dropped bits vs one half
    if (s >= 0) {
      if (s > 10) return false;
      q = static_cast<std::uint64_t>(m << s);
    } else {
      const int r = -s;
      if (r >= 120) return false;
      const unsigned __int128 whole = m >> r;
      const unsigned __int128 rest = m - (whole << r);
      const unsigned __int128 one_half = static_cast<unsigned __int128>(1)
                                         << (r - 1);
      half = rest == one_half;
      above = rest > one_half;
      q = static_cast<std::uint64_t>(whole);
    }
    if (q < ten16) {
      --e;
      continue;
    }
    if (q >= 10 * ten16) {
      ++e;
      continue;
    }
    if (above || (half && (q & 1))) ++q;
    if (q == 10 * ten16) {
      q = ten16;
      ++e;
    }
    d = q;
    e10 = e;
    return true;
  }
  return false;
}

}  // namespace

/// x as printf("%.17g", x) writes it, at `out`; returns the end (at most 24
/// characters later).
char* write_g17(double x, char* out) {
  std::uint64_t d = 0;
  int e = 0;
  if (x == 0 || !decimal_digits_17(std::fabs(x), d, e)) {
    return out + std::snprintf(out, 32, "%.17g", x);
  }
  if (std::signbit(x)) *out++ = '-';
  char digit[17];
  auto high = static_cast<std::uint32_t>(d / 100000000u);
  auto low = static_cast<std::uint32_t>(d % 100000000u);
  for (int i = 16; i >= 9; --i, low /= 10)
    digit[i] = static_cast<char>('0' + low % 10);
  for (int i = 8; i >= 0; --i, high /= 10)
    digit[i] = static_cast<char>('0' + high % 10);
  int n = 17;
  while (n > 1 && digit[n - 1] == '0') --n;  // %g drops trailing zeros
  if (e < -4) {  // d.ddde-05: the only exponent form in range
    *out++ = digit[0];
    if (n > 1) {
      *out++ = '.';
      std::memcpy(out, digit + 1, n - 1);
      out += n - 1;
    }
    *out++ = 'e';
    *out++ = '-';
    *out++ = static_cast<char>('0' + (-e) / 10);
    *out++ = static_cast<char>('0' + (-e) % 10);
    return out;
  }
  if (e < 0) {  // 0.000ddd
    *out++ = '0';
    *out++ = '.';
    for (int i = 0; i < -e - 1; ++i) *out++ = '0';
    std::memcpy(out, digit, n);
    return out + n;
  }
  const int whole = e + 1;  // e <= 16
  std::memcpy(out, digit, whole);
  out += whole;
  if (n > whole) {
    *out++ = '.';
    std::memcpy(out, digit + whole, n - whole);
    out += n - whole;
  }
  return out;
}

char* write_uint(std::uint64_t x, char* out) {
  char buf[20];
  int n = 0;
  do {
    buf[n++] = static_cast<char>('0' + x % 10);
    x /= 10;
  } while (x != 0);
  while (n > 0) *out++ = buf[--n];
  return out;
}

}  // namespace subdivlab::detail
