// The Messages panel's line: what the last action did, or why it could not. A problem is shown in
// the error colour; a confirmation ("saved ...", "course week3 opened") plainly, since it is none.
#pragma once
#include <string>
#include <utility>

namespace shadelab {

struct StatusLine {
  std::string text;
  bool problem = false;

  static StatusLine done(std::string text) { return {std::move(text), false}; }
  static StatusLine failed(std::string text) {
    const bool any = !text.empty();
    return {std::move(text), any};
  }
  // The usual outcome of an action that returns its error: `error`, or `doneText` when there is none.
  static StatusLine of(const std::string& error, std::string doneText) {
    return error.empty() ? done(std::move(doneText)) : failed(error);
  }
  bool empty() const { return text.empty(); }
};

}  // namespace shadelab
