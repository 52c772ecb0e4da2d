// Number formatting for reports and generated files.
#pragma once

#include <string>

namespace mirage {

/// The shortest text that reads back as the same double ("1.000233", "0.1", "nan", "inf").
std::string shortest(double v);

/// printf-style %.<digits>g.
std::string sig(double v, int digits);

}  // namespace mirage
