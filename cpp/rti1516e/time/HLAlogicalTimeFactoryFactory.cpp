// The factory of the standard time types by name: "HLAfloat64Time" (also the default, ""), "HLAinteger64Time".
#include <RTI/LogicalTimeFactory.h>
#include <RTI/time/HLAfloat64TimeFactory.h>
#include <RTI/time/HLAinteger64TimeFactory.h>

namespace rti1516e {

RTI_UNIQUE_PTR<LogicalTimeFactory> HLAlogicalTimeFactoryFactory::makeLogicalTimeFactory(
    std::wstring const& implementationName) {
    if (implementationName.empty() || implementationName == HLAfloat64TimeName)
        return RTI_UNIQUE_PTR<LogicalTimeFactory>(new HLAfloat64TimeFactory());
    if (implementationName == HLAinteger64TimeName)
        return RTI_UNIQUE_PTR<LogicalTimeFactory>(new HLAinteger64TimeFactory());
    return nullptr;
}

}  // namespace rti1516e
