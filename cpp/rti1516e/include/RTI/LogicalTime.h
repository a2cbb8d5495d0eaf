// A point of logical time (IEEE 1516.1-2010 §12.1): the interface both standard time types implement
// (RTI/time/HLAfloat64Time.h, RTI/time/HLAinteger64Time.h), and a federate's own could.
#ifndef RTI_LogicalTime_h
#define RTI_LogicalTime_h

#include <RTI/LogicalTimeInterval.h>

namespace rti1516e {

RTI1516E_LOGICAL_VALUE_INTERFACE(LogicalTime, setInitial, isInitial, setFinal, isFinal, )

}  // namespace rti1516e

#endif
