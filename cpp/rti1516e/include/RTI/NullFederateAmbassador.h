// A FederateAmbassador that ignores every callback: derive from it and override what the federate uses.
#ifndef RTI_NullFederateAmbassador_h
#define RTI_NullFederateAmbassador_h

#include <RTI/FederateAmbassador.h>

namespace rti1516e {

class RTI_EXPORT NullFederateAmbassador : public FederateAmbassador {
public:
    NullFederateAmbassador() = default;
    ~NullFederateAmbassador() override;
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
#define RTI1516E_IGNORED(ret, name, params, qualifier) ret name params qualifier override {}
    RTI1516E_CALLBACKS(RTI1516E_IGNORED)
#undef RTI1516E_IGNORED
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
};

}  // namespace rti1516e

#endif
