// The whole IEEE 1516.1-2010 C++ API in one include.
#ifndef RTI_RTI1516_h
#define RTI_RTI1516_h

#include <RTI/Enums.h>
#include <RTI/Exception.h>
#include <RTI/FederateAmbassador.h>
#include <RTI/Handle.h>
#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/NullFederateAmbassador.h>
#include <RTI/RTIambassador.h>
#include <RTI/RTIambassadorFactory.h>
#include <RTI/RangeBounds.h>
#include <RTI/SpecificConfig.h>
#include <RTI/Typedefs.h>
#include <RTI/VariableLengthData.h>

#include <string>

namespace rti1516e {
RTI_EXPORT std::wstring rtiName();     // L"hlacore"
RTI_EXPORT std::wstring rtiVersion();  // the standard and hlacore's version
}  // namespace rti1516e

#endif
