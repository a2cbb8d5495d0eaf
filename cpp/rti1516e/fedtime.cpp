// libfedtime1516e: the time types a federation can be created with. hlacore has only the standard two, so this
// hands the name on to librti1516e's HLAlogicalTimeFactoryFactory.
#include <RTI/LogicalTimeFactory.h>

namespace rti1516e {

RTI_UNIQUE_PTR<LogicalTimeFactory> LogicalTimeFactoryFactory::makeLogicalTimeFactory(
    std::wstring const& implementationName) {
    return HLAlogicalTimeFactoryFactory::makeLogicalTimeFactory(implementationName);
}

}  // namespace rti1516e
