// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_warnings_h
#define dpana_base_warnings_h

#include <algorithm>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * Adds @p text, one warning line, to @p warnings (the lines a body, the
   * references or the scene keep for summary.json) unless it is empty or
   * already there; returns whether it was added, i.e. whether it is new to
   * the log.
   */
  inline bool
  add_warning(std::vector<std::string> &warnings, const std::string &text)
  {
    if (text.empty() ||
        std::find(warnings.begin(), warnings.end(), text) != warnings.end())
      return false;
    warnings.push_back(text);
    return true;
  }
} // namespace dpana

#endif
