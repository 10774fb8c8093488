#pragma once
// What no log line, reply or error text may carry: credentials. One scrubber for any text, used by
// the log's sink (every line, whatever its level or source, library error texts included) and by
// the replies that echo what a client stored.
//  - URLs: "scheme://user:SECRET@host" -> "scheme://user:<redacted>@host", any scheme or case,
//    anywhere in the text (a user name alone is no secret and stays).
//  - Password commands: "\password SECRET" (rotctld/rigctld, any case) and host mode's "PASS SECRET"
//    as a quoted line ('PASS SECRET', the way the debug log quotes what a client sent) -> the secret
//    as <redacted>, up to the closing quote or the line's end.
#include <cctype>
#include <string>
#include <string_view>

namespace tb::redact {

inline constexpr std::string_view kRedacted = "<redacted>";

namespace detail {
inline bool iequal_at(std::string_view text, std::size_t at, std::string_view word) {
  if (at + word.size() > text.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[at + i])) != word[i]) return false;
  return true;
}
inline bool blank(char c) { return c == ' ' || c == '\t'; }
// Where a URL's authority ends: the first of / ? # or a character no URL has unescaped.
inline bool ends_authority(char c) {
  return c == '/' || c == '?' || c == '#' || std::isspace(static_cast<unsigned char>(c)) || c == '\'' || c == '"' ||
         c == '<' || c == '>' || c == ',' || c == ';' || c == '\0';
}
}  // namespace detail

// Every URL's password in `text` replaced by <redacted>.
inline std::string url_credentials(std::string_view text) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t scheme = text.find("://"); scheme != std::string_view::npos;
       scheme = text.find("://", scheme + 3)) {
    const std::size_t authority = scheme + 3;
    std::size_t end = authority;
    while (end < text.size() && !detail::ends_authority(text[end])) ++end;
    const std::string_view auth = text.substr(authority, end - authority);
    const std::size_t at = auth.rfind('@');
    if (at == std::string_view::npos) continue;
    const std::size_t colon = auth.substr(0, at).find(':');
    if (colon == std::string_view::npos) continue;  // a user name alone
    out.append(text.substr(from, authority + colon + 1 - from));
    out.append(kRedacted);
    from = authority + at;
  }
  if (from == 0) return std::string(text);
  out.append(text.substr(from));
  return out;
}

// The secret of every password command in `text` replaced by <redacted>.
inline std::string password_commands(std::string_view text) {
  std::string out;
  std::size_t from = 0;
  auto redact_word_after = [&](std::size_t word_end) {
    std::size_t s = word_end;
    while (s < text.size() && detail::blank(text[s])) ++s;
    if (s == word_end || s >= text.size()) return word_end;  // "PASS" alone or no blank: nothing
    std::size_t e = s;
    while (e < text.size() && text[e] != '\'' && text[e] != '\r' && text[e] != '\n') ++e;
    out.append(text.substr(from, s - from));
    out.append(kRedacted);
    from = e;
    return e;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && detail::iequal_at(text, i + 1, "password")) {
      i = redact_word_after(i + 9) - 1;
    } else if (i > 0 && text[i - 1] == '\'' && detail::iequal_at(text, i, "pass") &&
               (i + 4 < text.size() && detail::blank(text[i + 4]))) {
      i = redact_word_after(i + 4) - 1;
    }
  }
  if (from == 0) return std::string(text);
  out.append(text.substr(from));
  return out;
}

// Every occurrence of a secret trakbox holds (the logger's API key) in `text`, in any case,
// replaced by <redacted>: for what an outside server's reply quotes back (a 401 naming the key
// it refused) before it is logged or shown. A secret shorter than 4 characters is no key and is
// left alone (it would redact ordinary words).
inline std::string secret(std::string_view text, std::string_view secret_value) {
  if (secret_value.size() < 4 || text.size() < secret_value.size()) return std::string(text);
  std::string out;
  std::size_t from = 0;
  for (std::size_t i = 0; i + secret_value.size() <= text.size();) {
    bool same = true;
    for (std::size_t k = 0; k < secret_value.size() && same; ++k)
      same = std::tolower(static_cast<unsigned char>(text[i + k])) ==
             std::tolower(static_cast<unsigned char>(secret_value[k]));
    if (!same) {
      ++i;
      continue;
    }
    out.append(text.substr(from, i - from));
    out.append(kRedacted);
    i += secret_value.size();
    from = i;
  }
  if (from == 0) return std::string(text);
  out.append(text.substr(from));
  return out;
}

// Both: what a log line or an echoed setting is written as.
inline std::string text(std::string_view t) { return password_commands(url_credentials(t)); }

}  // namespace tb::redact
