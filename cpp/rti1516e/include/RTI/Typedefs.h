// The collections and records of IEEE 1516.1-2010's C++ API.
#ifndef RTI_Typedefs_h
#define RTI_Typedefs_h

#include <RTI/Enums.h>
#include <RTI/Handle.h>
#include <RTI/SpecificConfig.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rti1516e {

typedef std::set<AttributeHandle> AttributeHandleSet;
typedef std::set<ParameterHandle> ParameterHandleSet;
typedef std::set<FederateHandle> FederateHandleSet;
typedef std::set<DimensionHandle> DimensionHandleSet;
typedef std::set<RegionHandle> RegionHandleSet;
typedef std::map<AttributeHandle, VariableLengthData> AttributeHandleValueMap;
typedef std::map<ParameterHandle, VariableLengthData> ParameterHandleValueMap;
typedef std::pair<AttributeHandleSet, RegionHandleSet> AttributeHandleSetRegionHandleSetPair;
typedef std::vector<AttributeHandleSetRegionHandleSetPair> AttributeHandleSetRegionHandleSetPairVector;
typedef std::pair<FederateHandle, SaveStatus> FederateHandleSaveStatusPair;
typedef std::vector<FederateHandleSaveStatusPair> FederateHandleSaveStatusPairVector;

class RTI_EXPORT FederateRestoreStatus {
public:
    FederateRestoreStatus(FederateHandle const& thePreHandle, FederateHandle const& thePostHandle,
                          RestoreStatus theStatus)
        : preRestoreHandle(thePreHandle), postRestoreHandle(thePostHandle), status(theStatus) {}
    FederateHandle preRestoreHandle;
    FederateHandle postRestoreHandle;
    RestoreStatus status;
};
typedef std::vector<FederateRestoreStatus> FederateRestoreStatusVector;

class RTI_EXPORT FederationExecutionInformation {
public:
    FederationExecutionInformation(std::wstring const& theFederationExecutionName,
                                   std::wstring const& theLogicalTimeImplementationName)
        : federationExecutionName(theFederationExecutionName),
          logicalTimeImplementationName(theLogicalTimeImplementationName) {}
    std::wstring federationExecutionName;
    std::wstring logicalTimeImplementationName;
};
typedef std::vector<FederationExecutionInformation> FederationExecutionInformationVector;

// What a reflection (SupplementalReflectInfo) or an interaction (SupplementalReceiveInfo) says of its sender
// and of the regions it was sent with.
#define RTI1516E_SUPPLEMENTAL_INFO(Class)                                                                     \
    class RTI_EXPORT Class {                                                                                  \
    public:                                                                                                   \
        Class() = default;                                                                                    \
        Class(FederateHandle const& theFederateHandle)                                                        \
            : hasProducingFederate(true), producingFederate(theFederateHandle) {}                             \
        Class(RegionHandleSet const& theRegionHandleSet) : hasSentRegions(true), sentRegions(theRegionHandleSet) {} \
        Class(FederateHandle const& theFederateHandle, RegionHandleSet const& theRegionHandleSet)             \
            : hasProducingFederate(true), hasSentRegions(true), producingFederate(theFederateHandle),          \
              sentRegions(theRegionHandleSet) {}                                                              \
        bool hasProducingFederate = false;                                                                    \
        bool hasSentRegions = false;                                                                          \
        FederateHandle producingFederate;                                                                     \
        RegionHandleSet sentRegions;                                                                          \
    };
RTI1516E_SUPPLEMENTAL_INFO(SupplementalReflectInfo)
RTI1516E_SUPPLEMENTAL_INFO(SupplementalReceiveInfo)

class RTI_EXPORT SupplementalRemoveInfo {
public:
    SupplementalRemoveInfo() = default;
    SupplementalRemoveInfo(FederateHandle const& theFederateHandle)
        : hasProducingFederate(true), producingFederate(theFederateHandle) {}
    bool hasProducingFederate = false;
    FederateHandle producingFederate;
};

}  // namespace rti1516e

#endif
