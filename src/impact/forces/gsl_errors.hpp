// GSL's default error handler aborts the process. The library turns it off around its own GSL
// calls, checks every status itself and reports a failure as an exception, and restores whatever
// handler the program had, so the process-wide setting is left as it was.
#pragma once

#include <gsl/gsl_errno.h>

namespace impact {

class GslErrorsAsStatus {
 public:
  GslErrorsAsStatus() : previous_(gsl_set_error_handler_off()) {}
  GslErrorsAsStatus(const GslErrorsAsStatus&) = delete;
  GslErrorsAsStatus& operator=(const GslErrorsAsStatus&) = delete;
  ~GslErrorsAsStatus() { gsl_set_error_handler(previous_); }

 private:
  gsl_error_handler_t* previous_;
};

}  // namespace impact
