// harness_text.cxx - escaping and number formatting (harness_text.h).
#include "harness_text.h"

#include <cstdio>

namespace vsh_harness
{

std::string HtmlEscape(const std::string& s)
{
  std::string o;
  for (char c : s)
  {
    switch (c)
    {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string JsonEscape(const std::string& s)
{
  std::string o;
  for (unsigned char c : s)
  {
    if (c == '"' || c == '\\')
    {
      o += '\\';
      o += static_cast<char>(c);
    }
    else if (c < 0x20)
    {
      char buf[8];
      snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    }
    else
      o += static_cast<char>(c);
  }
  return o;
}

std::string Fmt(double v, const char* fmt)
{
  char buf[64];
  snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

} // namespace vsh_harness
