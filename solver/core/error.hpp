// Error types shared by every module. The CLI maps them to exit codes:
// InputError -> 2, NonConvergence -> 3, SolverError -> 4.
#pragma once

#include <stdexcept>
#include <string>

namespace kontakt {

/// Where a piece of input came from; line is 1-based, 0 when unknown.
struct SourceLoc {
  std::string file;
  int line = 0;
};

/// A user error in the deck: always names file, line and keyword.
class InputError : public std::runtime_error {
 public:
  InputError(const SourceLoc& where, const std::string& keyword, const std::string& message);
  const SourceLoc& where() const { return where_; }
  const std::string& keyword() const { return keyword_; }

 private:
  SourceLoc where_;
  std::string keyword_;
};

/// A numerical failure that is not the user's fault of syntax: singular stiffness,
/// rigid-body modes, NaN, a failed factorisation.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The nonlinear iteration did not converge (minimum increment or cutback limit reached).
class NonConvergence : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace kontakt

/// Always-on check for conditions a user or the environment can break.
#define KONTAKT_REQUIRE(cond, msg)                      \
  do {                                                  \
    if (!(cond)) throw ::kontakt::SolverError(msg);     \
  } while (0)
