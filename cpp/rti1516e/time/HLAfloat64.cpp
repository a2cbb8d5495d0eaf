// HLAfloat64Time, HLAfloat64Interval and HLAfloat64TimeFactory. Final is +infinity, as in CERTI's 1516e time
// (RTI1516fedTime), hlacore's HLA 1.3 RTIfedTime, and the core, which sends infinity for a time nothing bounds:
// no finite time is then past the end. Epsilon is the smallest positive double (a denormal).
#include <RTI/time/HLAfloat64TimeFactory.h>

#include <limits>

#include "TimeValue.h"

namespace rti1516e {

HLACORE_TIME_TYPE(HLAfloat64Time, HLAfloat64Interval, HLAfloat64TimeFactory, double,
                  HLAfloat64TimeName,
                  std::numeric_limits<double>::infinity(), std::numeric_limits<double>::denorm_min())

}  // namespace rti1516e
