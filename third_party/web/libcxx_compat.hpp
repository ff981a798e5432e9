// What the browser build's C++ library lacks of C++20, supplied for that build alone.
//
// Debian's emscripten 3.1.6 ships libc++ 13, which has no floating-point std::to_chars or
// std::from_chars and no std::jthread; the desktop's libstdc++ 12 has all three and the code
// uses them as the standard says. Rather than wrap every call, third_party/web/web.cmake
// force-includes this header into every browser-build translation unit (-include), so the same
// source compiles for both targets. Nothing here is compiled into the desktop build.
//
// - to_chars(double): the shortest digits that read back to the same double (the standard's
//   round-trip guarantee), found as the least printf precision whose digits strtod maps back
//   to the value: printf rounds correctly, so if any string of that many digits round-trips,
//   its (the nearest one) does. Fixed or scientific notation, whichever is shorter (fixed on a
//   tie), spelt in the standard's printf style ("1e+20", "0.001", "inf", "-nan").
// - to_chars(double, scientific): the same digits, always in scientific notation.
// - to_chars(double, fmt, precision): exactly printf with that precision, as the standard
//   specifies it.
// - from_chars(double): the standard's pattern (no leading '+' or space, no "0x") checked
//   here, its characters converted by strtod (the "C" locale is the only one in a browser).
// - bit_cast: the compiler's builtin, which libc++ 14 wraps the same way.
// - jthread and stop_token: a page without COOP/COEP headers has no threads, and starting a
//   std::thread there throws. This jthread runs its function to completion inside its
//   constructor: a background job (ui/view/implicit_meshes.cpp) is finished when started and
//   its caller sees it done the next time it looks.
//
// The conversions themselves (namespace isoparm_web_compat) are plain C++: the desktop's tests
// compile them with ISOPARM_WEB_COMPAT_TEST and compare them with libstdc++'s
// (tests/web/charconv_compat_test.cpp).
#pragma once

#if defined(__EMSCRIPTEN__) && defined(__cplusplus)
#include <ciso646> // defines _LIBCPP_VERSION
#endif

#if defined(__EMSCRIPTEN__) && defined(__cplusplus) && defined(_LIBCPP_VERSION) &&                 \
    _LIBCPP_VERSION < 14000
#define ISOPARM_WEB_COMPAT_STD 1
#endif

#if defined(ISOPARM_WEB_COMPAT_STD) || defined(ISOPARM_WEB_COMPAT_TEST)

#include <atomic>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>

namespace isoparm_web_compat {

// Shortest round-trip digits of a finite, non-zero |x|: digits "d1d2...dn" and the decimal
// exponent e of d1.d2...dn x 10^e.
inline void shortest_digits(double x, std::string& digits, int& exponent) {
    char buf[40];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*e", precision - 1, x);
        if (std::strtod(buf, nullptr) == x || precision == 17) break;
    }
    // buf is "d.ddddde+XX" (or "de+XX" for one digit).
    const char* e = std::strchr(buf, 'e');
    digits.clear();
    for (const char* p = buf; p < e; ++p)
        if (*p != '.') digits += *p;
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    exponent = std::atoi(e + 1);
}

// |x| in fixed notation from its shortest digits. Past the digits the value is an integer, and
// of the spellings of that length the standard takes the nearest: the exact one (%.0f).
inline std::string fixed_text(double x, const std::string& d, int e) {
    const int n = static_cast<int>(d.size());
    if (e >= n - 1) {
        char buf[400];
        std::snprintf(buf, sizeof buf, "%.0f", std::fabs(x));
        return buf;
    }
    if (e >= 0) return d.substr(0, e + 1) + "." + d.substr(e + 1);
    return "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + d;
}

inline std::string scientific_text(const std::string& d, int e) {
    std::string s = d.substr(0, 1);
    if (d.size() > 1) s += "." + d.substr(1);
    char exp[16];
    std::snprintf(exp, sizeof exp, "e%c%02d", e < 0 ? '-' : '+', e < 0 ? -e : e);
    return s + exp;
}

// 0: shortest of fixed and scientific; 1: scientific.
inline std::string shortest_text(double x, int style) {
    if (std::isnan(x)) return std::signbit(x) ? "-nan" : "nan";
    const std::string sign = std::signbit(x) ? "-" : "";
    if (std::isinf(x)) return sign + "inf";
    if (x == 0) return sign + (style == 1 ? "0e+00" : "0");
    std::string digits;
    int exponent = 0;
    shortest_digits(std::fabs(x), digits, exponent);
    const std::string sci = scientific_text(digits, exponent);
    if (style == 1) return sign + sci;
    const std::string fix = fixed_text(x, digits, exponent);
    return sign + (fix.size() <= sci.size() ? fix : sci);
}

inline std::to_chars_result copy_out(char* first, char* last, const std::string& s) {
    if (static_cast<std::ptrdiff_t>(s.size()) > last - first)
        return {last, std::errc::value_too_large};
    std::memcpy(first, s.data(), s.size());
    return {first + s.size(), std::errc{}};
}

inline bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

inline bool starts_with_nocase(const char* p, const char* last, const char* word) {
    for (; *word; ++word, ++p)
        if (p == last || (*p | 0x20) != *word) return false;
    return true;
}

// from_chars for a double: 0, EINVAL (no number) or ERANGE (too large or too small: `value`
// untouched); `end` is where the number ends.
inline int parse_double(const char* first, const char* last, double& value, std::chars_format fmt,
                        const char*& end) {
    const char* p = first;
    end = first;
    if (p != last && *p == '-') ++p;
    const char* body = p;
    if (starts_with_nocase(p, last, "inf")) {
        p += starts_with_nocase(p, last, "infinity") ? 8 : 3;
    } else if (starts_with_nocase(p, last, "nan")) {
        p += 3;
        if (p != last && *p == '(') { // nan(n-char-sequence)
            const char* q = p + 1;
            while (q != last &&
                   (is_digit(*q) || std::isalpha(static_cast<unsigned char>(*q)) || *q == '_'))
                ++q;
            if (q != last && *q == ')') p = q + 1;
        }
    } else {
        int digits = 0;
        while (p != last && is_digit(*p)) ++p, ++digits;
        if (p != last && *p == '.') {
            ++p;
            while (p != last && is_digit(*p)) ++p, ++digits;
        }
        if (digits == 0) return EINVAL;
        const bool may_exp = fmt != std::chars_format::fixed;
        const bool must_exp = fmt == std::chars_format::scientific;
        bool had_exp = false;
        if (may_exp && p != last && (*p == 'e' || *p == 'E')) {
            const char* q = p + 1;
            if (q != last && (*q == '+' || *q == '-')) ++q;
            if (q != last && is_digit(*q)) {
                while (q != last && is_digit(*q)) ++q;
                p = q;
                had_exp = true;
            }
        }
        if (must_exp && !had_exp) return EINVAL;
    }
    if (p == body) return EINVAL;
    end = p;
    if ((*body | 0x20) == 'n') { // a NaN's payload is not read: the quiet NaN, with its sign
        value = std::copysign(std::numeric_limits<double>::quiet_NaN(), body == first ? 1.0 : -1.0);
        return 0;
    }
    const std::string text(first, p);
    errno = 0;
    const double x = std::strtod(text.c_str(), nullptr);
    if (errno == ERANGE && (std::isinf(x) || x == 0)) return ERANGE;
    value = x;
    return 0;
}

} // namespace isoparm_web_compat

#endif

#ifdef ISOPARM_WEB_COMPAT_STD

namespace std {

template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
         is_trivially_copyable_v<From>) constexpr To bit_cast(const From& from) noexcept {
    return __builtin_bit_cast(To, from);
}

inline to_chars_result to_chars(char* first, char* last, double value) {
    return isoparm_web_compat::copy_out(first, last, isoparm_web_compat::shortest_text(value, 0));
}

inline to_chars_result to_chars(char* first, char* last, double value, chars_format fmt) {
    if (fmt == chars_format::scientific)
        return isoparm_web_compat::copy_out(first, last,
                                            isoparm_web_compat::shortest_text(value, 1));
    if (fmt == chars_format::hex) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%a", value);
        const char* s = buf[0] == '-' ? buf + 1 : buf;
        std::string text = buf[0] == '-' ? "-" : "";
        text += s[0] == '0' && s[1] == 'x' ? s + 2 : s; // to_chars writes no "0x"
        return isoparm_web_compat::copy_out(first, last, text);
    }
    if (fmt == chars_format::fixed && std::isfinite(value) && value != 0) {
        std::string digits;
        int exponent = 0;
        isoparm_web_compat::shortest_digits(std::fabs(value), digits, exponent);
        return isoparm_web_compat::copy_out(
            first, last,
            (std::signbit(value) ? "-" : "") +
                isoparm_web_compat::fixed_text(value, digits, exponent));
    }
    return to_chars(first, last, value); // general: as the plain overload
}

inline to_chars_result to_chars(char* first, char* last, double value, chars_format fmt,
                                int precision) {
    const char* spec = fmt == chars_format::scientific ? "%.*e"
                       : fmt == chars_format::fixed    ? "%.*f"
                       : fmt == chars_format::hex      ? "%.*a"
                                                       : "%.*g";
    const int n = std::snprintf(nullptr, 0, spec, precision, value);
    std::string s(static_cast<std::size_t>(n) + 1, '\0');
    std::snprintf(s.data(), s.size(), spec, precision, value);
    s.resize(static_cast<std::size_t>(n));
    if (fmt == chars_format::hex) {
        const std::size_t x = s.find("0x");
        if (x != std::string::npos) s.erase(x, 2);
    }
    return isoparm_web_compat::copy_out(first, last, s);
}

inline from_chars_result from_chars(const char* first, const char* last, double& value,
                                    chars_format fmt = chars_format::general) {
    const char* end = first;
    const int e = isoparm_web_compat::parse_double(first, last, value, fmt, end);
    return {end, e == 0        ? errc{}
                 : e == ERANGE ? errc::result_out_of_range
                               : errc::invalid_argument};
}

// A stop state shared by a jthread and its tokens.
class stop_token {
public:
    stop_token() noexcept = default;
    bool stop_requested() const noexcept { return state_ && state_->load(); }
    bool stop_possible() const noexcept { return static_cast<bool>(state_); }

private:
    friend class stop_source;
    explicit stop_token(std::shared_ptr<std::atomic<bool>> s) : state_(std::move(s)) {}
    std::shared_ptr<std::atomic<bool>> state_;
};

class stop_source {
public:
    stop_source() : state_(std::make_shared<std::atomic<bool>>(false)) {}
    bool request_stop() noexcept { return state_ && !state_->exchange(true); }
    bool stop_requested() const noexcept { return state_ && state_->load(); }
    stop_token get_token() const noexcept { return stop_token(state_); }

private:
    std::shared_ptr<std::atomic<bool>> state_;
};

class jthread {
public:
    jthread() noexcept = default;
    template <class F, class... Args,
              class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, jthread>>>
    explicit jthread(F&& f, Args&&... args) : source_() {
        if constexpr (std::is_invocable_v<std::decay_t<F>, stop_token, std::decay_t<Args>...>)
            std::invoke(std::forward<F>(f), source_.get_token(), std::forward<Args>(args)...);
        else
            std::invoke(std::forward<F>(f), std::forward<Args>(args)...);
    }
    jthread(jthread&&) noexcept = default;
    jthread& operator=(jthread&& o) noexcept {
        request_stop();
        source_ = std::move(o.source_);
        return *this;
    }
    ~jthread() = default;
    bool joinable() const noexcept { return false; } // the work is done: nothing to join
    void join() {}
    void detach() {}
    bool request_stop() noexcept { return source_.request_stop(); }
    stop_token get_stop_token() const noexcept { return source_.get_token(); }
    stop_source get_stop_source() const noexcept { return source_; }

private:
    stop_source source_;
};

} // namespace std

#endif
