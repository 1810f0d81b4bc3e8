// harness_text.h - text of the reports: escaping for HTML and JSON, numbers.
#ifndef VTKSHADOW_HARNESS_TEXT_H
#define VTKSHADOW_HARNESS_TEXT_H

#include <string>

namespace vsh_harness
{

std::string HtmlEscape(const std::string& s);
std::string JsonEscape(const std::string& s);
std::string Fmt(double v, const char* fmt = "%.17g");

} // namespace vsh_harness

#endif
