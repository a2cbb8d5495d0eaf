// HLAinteger64Time, HLAinteger64Interval and HLAinteger64TimeFactory. Final is the largest Integer64 (a sum past
// it throws IllegalTimeArithmetic); epsilon is 1.
#include <RTI/time/HLAinteger64TimeFactory.h>

#include <limits>

#include "TimeValue.h"

namespace rti1516e {

HLACORE_TIME_TYPE(HLAinteger64Time, HLAinteger64Interval, HLAinteger64TimeFactory, Integer64,
                  HLAinteger64TimeName, std::numeric_limits<Integer64>::max(), 1)

}  // namespace rti1516e
