// Makes an RTIambassador (hlacore's, over its federate-side client).
#ifndef RTI_RTIambassadorFactory_h
#define RTI_RTIambassadorFactory_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>

#include <memory>

namespace rti1516e {

class RTIambassador;

class RTI_EXPORT RTIambassadorFactory {
public:
    RTIambassadorFactory() = default;
    virtual ~RTIambassadorFactory();
    RTI_UNIQUE_PTR<RTIambassador> createRTIambassador();
};

}  // namespace rti1516e

#endif
