// The calls: each CallRequest onto the session's RTIambassador, its result into the CallResponse. What HLA 4 adds
// and the core does not serve is answered with the standard's exception, never dropped.
#include <RTI/encoding/BasicDataElements.h>

#include "fedpro/hla_federate.hpp"
#include "rti1516e/ambassador.hpp"

namespace hlacore::fedpro {

namespace {

[[noreturn]] void not_served(const char* service, const char* why) {
    throw api::RTIinternalError(wide(std::string("RTIinternalError: ") + service + " is not served by hlacore: " + why));
}

api::VariableLengthData tag(std::string const& t) { return data(t); }

constexpr const char* kPlainTextPassword = "HLAplainTextPassword";

// HLAplainTextPassword's data, an HLAunicodeString, as UTF-8; InvalidCredentials when it is not one.
std::string password(std::string const& data) {
    try {
        api::HLAunicodeString text;
        text.decode(api::VariableLengthData(data.data(), data.size()));
        return utf8(text.get());
    } catch (api::EncoderException const&) {
        throw Hla4Exception("InvalidCredentials", "HLAplainTextPassword credentials that are not an HLAunicodeString");
    }
}

// Compared in constant time: how long it takes says nothing of where they differ.
bool same_secret(std::string const& a, std::string const& b) {
    unsigned char differ = a.size() != b.size();
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) differ |= static_cast<unsigned char>(a[i] ^ b[i]);
    return differ == 0;
}

}  // namespace

void HlaFederate::serve(pb::CallRequest const& q, pb::CallResponse& r) {
    using C = pb::CallRequest;
    switch (q.callRequest_case()) {
        // ---- federation management ----
        // The session's federate joins the gateway this server serves, whatever configuration it names.
        case C::kConnectRequest:
            connect(nullptr);
            r.mutable_connectresponse()->mutable_configurationresult();
            return;
        case C::kConnectWithConfigurationRequest:
            declared(q.connectwithconfigurationrequest().rticonfiguration());
            connect(nullptr);
            r.mutable_connectwithconfigurationresponse()->mutable_configurationresult()->set_configurationused(false);
            return;
        case C::kConnectWithCredentialsRequest:
            connect(&q.connectwithcredentialsrequest().credentials());
            r.mutable_connectwithcredentialsresponse()->mutable_configurationresult();
            return;
        case C::kConnectWithConfigurationAndCredentialsRequest:
            declared(q.connectwithconfigurationandcredentialsrequest().rticonfiguration());
            connect(&q.connectwithconfigurationandcredentialsrequest().credentials());
            r.mutable_connectwithconfigurationandcredentialsresponse()->mutable_configurationresult()->set_configurationused(false);
            return;
        case C::kDisconnectRequest:
            rti_->disconnect();
            r.mutable_disconnectresponse();
            return;
        case C::kCreateFederationExecutionRequest: {
            auto const& m = q.createfederationexecutionrequest();
            rti_->createFederationExecution(wide(m.federationname()), module(m.fommodule()));
            r.mutable_createfederationexecutionresponse();
            return;
        }
        case C::kCreateFederationExecutionWithTimeRequest: {
            auto const& m = q.createfederationexecutionwithtimerequest();
            rti_->createFederationExecution(wide(m.federationname()), module(m.fommodule()), wide(m.logicaltimeimplementationname()));
            r.mutable_createfederationexecutionwithtimeresponse();
            return;
        }
        case C::kCreateFederationExecutionWithModulesRequest: {
            auto const& m = q.createfederationexecutionwithmodulesrequest();
            rti_->createFederationExecution(wide(m.federationname()), modules(m.fommodules()));
            r.mutable_createfederationexecutionwithmodulesresponse();
            return;
        }
        case C::kCreateFederationExecutionWithModulesAndTimeRequest: {
            auto const& m = q.createfederationexecutionwithmodulesandtimerequest();
            rti_->createFederationExecution(wide(m.federationname()), modules(m.fommodules()), wide(m.logicaltimeimplementationname()));
            r.mutable_createfederationexecutionwithmodulesandtimeresponse();
            return;
        }
        case C::kCreateFederationExecutionWithMIMRequest: {
            auto const& m = q.createfederationexecutionwithmimrequest();
            rti_->createFederationExecutionWithMIM(wide(m.federationname()), modules(m.fommodules()), module(m.mimmodule()));
            r.mutable_createfederationexecutionwithmimresponse();
            return;
        }
        case C::kCreateFederationExecutionWithMIMAndTimeRequest: {
            auto const& m = q.createfederationexecutionwithmimandtimerequest();
            rti_->createFederationExecutionWithMIM(wide(m.federationname()), modules(m.fommodules()), module(m.mimmodule()),
                                                   wide(m.logicaltimeimplementationname()));
            r.mutable_createfederationexecutionwithmimandtimeresponse();
            return;
        }
        case C::kDestroyFederationExecutionRequest:
            rti_->destroyFederationExecution(wide(q.destroyfederationexecutionrequest().federationname()));
            r.mutable_destroyfederationexecutionresponse();
            return;
        case C::kListFederationExecutionsRequest:
            rti_->listFederationExecutions();
            r.mutable_listfederationexecutionsresponse();
            return;
        case C::kJoinFederationExecutionRequest: {
            auto const& m = q.joinfederationexecutionrequest();
            joined(rti_->joinFederationExecution(wide(m.federatetype()), wide(m.federationname())),
                   m.federationname(), r.mutable_joinfederationexecutionresponse()->mutable_result());
            return;
        }
        case C::kJoinFederationExecutionWithModulesRequest: {
            auto const& m = q.joinfederationexecutionwithmodulesrequest();
            joined(rti_->joinFederationExecution(wide(m.federatetype()), wide(m.federationname()), modules(m.additionalfommodules())),
                   m.federationname(), r.mutable_joinfederationexecutionwithmodulesresponse()->mutable_result());
            return;
        }
        case C::kJoinFederationExecutionWithNameRequest: {
            auto const& m = q.joinfederationexecutionwithnamerequest();
            joined(rti_->joinFederationExecution(wide(m.federatename()), wide(m.federatetype()), wide(m.federationname())),
                   m.federationname(), r.mutable_joinfederationexecutionwithnameresponse()->mutable_result());
            return;
        }
        case C::kJoinFederationExecutionWithNameAndModulesRequest: {
            auto const& m = q.joinfederationexecutionwithnameandmodulesrequest();
            joined(rti_->joinFederationExecution(wide(m.federatename()), wide(m.federatetype()), wide(m.federationname()),
                                                 modules(m.additionalfommodules())),
                   m.federationname(), r.mutable_joinfederationexecutionwithnameandmodulesresponse()->mutable_result());
            return;
        }
        case C::kResignFederationExecutionRequest:
            rti_->resignFederationExecution(static_cast<api::ResignAction>(q.resignfederationexecutionrequest().resignaction()));
            left();
            r.mutable_resignfederationexecutionresponse();
            return;
        case C::kRegisterFederationSynchronizationPointRequest: {
            auto const& m = q.registerfederationsynchronizationpointrequest();
            rti_->registerFederationSynchronizationPoint(wide(m.synchronizationpointlabel()), tag(m.usersuppliedtag()));
            r.mutable_registerfederationsynchronizationpointresponse();
            return;
        }
        case C::kRegisterFederationSynchronizationPointWithSetRequest: {
            auto const& m = q.registerfederationsynchronizationpointwithsetrequest();
            rti_->registerFederationSynchronizationPoint(wide(m.synchronizationpointlabel()), tag(m.usersuppliedtag()),
                                                         federates(m.synchronizationset()));
            r.mutable_registerfederationsynchronizationpointwithsetresponse();
            return;
        }
        case C::kSynchronizationPointAchievedRequest: {
            auto const& m = q.synchronizationpointachievedrequest();
            rti_->synchronizationPointAchieved(wide(m.synchronizationpointlabel()), m.successfully());
            r.mutable_synchronizationpointachievedresponse();
            return;
        }
        case C::kRequestFederationSaveRequest:
            rti_->requestFederationSave(wide(q.requestfederationsaverequest().label()));
            r.mutable_requestfederationsaveresponse();
            return;
        case C::kRequestFederationSaveWithTimeRequest: {
            auto const& m = q.requestfederationsavewithtimerequest();
            rti_->requestFederationSave(wide(m.label()), *time(m.time()));
            r.mutable_requestfederationsavewithtimeresponse();
            return;
        }
        case C::kFederateSaveBegunRequest:
            rti_->federateSaveBegun();
            r.mutable_federatesavebegunresponse();
            return;
        case C::kFederateSaveCompleteRequest:
            rti_->federateSaveComplete();
            r.mutable_federatesavecompleteresponse();
            return;
        case C::kFederateSaveNotCompleteRequest:
            rti_->federateSaveNotComplete();
            r.mutable_federatesavenotcompleteresponse();
            return;
        case C::kAbortFederationSaveRequest:
            rti_->abortFederationSave();
            r.mutable_abortfederationsaveresponse();
            return;
        case C::kQueryFederationSaveStatusRequest:
            rti_->queryFederationSaveStatus();
            r.mutable_queryfederationsavestatusresponse();
            return;
        case C::kRequestFederationRestoreRequest:
            rti_->requestFederationRestore(wide(q.requestfederationrestorerequest().label()));
            r.mutable_requestfederationrestoreresponse();
            return;
        case C::kFederateRestoreCompleteRequest:
            rti_->federateRestoreComplete();
            r.mutable_federaterestorecompleteresponse();
            return;
        case C::kFederateRestoreNotCompleteRequest:
            rti_->federateRestoreNotComplete();
            r.mutable_federaterestorenotcompleteresponse();
            return;
        case C::kAbortFederationRestoreRequest:
            rti_->abortFederationRestore();
            r.mutable_abortfederationrestoreresponse();
            return;
        case C::kQueryFederationRestoreStatusRequest:
            rti_->queryFederationRestoreStatus();
            r.mutable_queryfederationrestorestatusresponse();
            return;

        // ---- declaration management ----
        case C::kPublishObjectClassAttributesRequest: {
            auto const& m = q.publishobjectclassattributesrequest();
            rti_->publishObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()));
            r.mutable_publishobjectclassattributesresponse();
            return;
        }
        case C::kUnpublishObjectClassRequest:
            rti_->unpublishObjectClass(object_class(q.unpublishobjectclassrequest().objectclass()));
            r.mutable_unpublishobjectclassresponse();
            return;
        case C::kUnpublishObjectClassAttributesRequest: {
            auto const& m = q.unpublishobjectclassattributesrequest();
            rti_->unpublishObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()));
            r.mutable_unpublishobjectclassattributesresponse();
            return;
        }
        case C::kPublishInteractionClassRequest:
            rti_->publishInteractionClass(interaction_class(q.publishinteractionclassrequest().interactionclass()));
            r.mutable_publishinteractionclassresponse();
            return;
        case C::kUnpublishInteractionClassRequest:
            rti_->unpublishInteractionClass(interaction_class(q.unpublishinteractionclassrequest().interactionclass()));
            r.mutable_unpublishinteractionclassresponse();
            return;
        case C::kSubscribeObjectClassAttributesRequest: {
            auto const& m = q.subscribeobjectclassattributesrequest();
            rti_->subscribeObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()));
            r.mutable_subscribeobjectclassattributesresponse();
            return;
        }
        case C::kSubscribeObjectClassAttributesWithRateRequest: {
            auto const& m = q.subscribeobjectclassattributeswithraterequest();
            rti_->subscribeObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()), true,
                                                 wide(m.updateratedesignator()));
            r.mutable_subscribeobjectclassattributeswithrateresponse();
            return;
        }
        case C::kSubscribeObjectClassAttributesPassivelyRequest: {
            auto const& m = q.subscribeobjectclassattributespassivelyrequest();
            rti_->subscribeObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()), false);
            r.mutable_subscribeobjectclassattributespassivelyresponse();
            return;
        }
        case C::kSubscribeObjectClassAttributesPassivelyWithRateRequest: {
            auto const& m = q.subscribeobjectclassattributespassivelywithraterequest();
            rti_->subscribeObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()), false,
                                                 wide(m.updateratedesignator()));
            r.mutable_subscribeobjectclassattributespassivelywithrateresponse();
            return;
        }
        case C::kUnsubscribeObjectClassRequest:
            rti_->unsubscribeObjectClass(object_class(q.unsubscribeobjectclassrequest().objectclass()));
            r.mutable_unsubscribeobjectclassresponse();
            return;
        case C::kUnsubscribeObjectClassAttributesRequest: {
            auto const& m = q.unsubscribeobjectclassattributesrequest();
            rti_->unsubscribeObjectClassAttributes(object_class(m.objectclass()), attributes(m.attributes()));
            r.mutable_unsubscribeobjectclassattributesresponse();
            return;
        }
        case C::kSubscribeInteractionClassRequest:
            rti_->subscribeInteractionClass(interaction_class(q.subscribeinteractionclassrequest().interactionclass()));
            r.mutable_subscribeinteractionclassresponse();
            return;
        case C::kSubscribeInteractionClassPassivelyRequest:
            rti_->subscribeInteractionClass(interaction_class(q.subscribeinteractionclasspassivelyrequest().interactionclass()), false);
            r.mutable_subscribeinteractionclasspassivelyresponse();
            return;
        case C::kUnsubscribeInteractionClassRequest:
            rti_->unsubscribeInteractionClass(interaction_class(q.unsubscribeinteractionclassrequest().interactionclass()));
            r.mutable_unsubscribeinteractionclassresponse();
            return;
        case C::kPublishObjectClassDirectedInteractionsRequest: {
            auto const& m = q.publishobjectclassdirectedinteractionsrequest();
            hla4("publishObjectClassDirectedInteractions")
                .publishObjectClassDirectedInteractions(object_class(m.objectclass()), interaction_classes(m.interactionclasses()));
            r.mutable_publishobjectclassdirectedinteractionsresponse();
            return;
        }
        case C::kUnpublishObjectClassDirectedInteractionsRequest:
            hla4("unpublishObjectClassDirectedInteractions")
                .unpublishObjectClassDirectedInteractions(object_class(q.unpublishobjectclassdirectedinteractionsrequest().objectclass()));
            r.mutable_unpublishobjectclassdirectedinteractionsresponse();
            return;
        case C::kUnpublishObjectClassDirectedInteractionsWithSetRequest: {
            auto const& m = q.unpublishobjectclassdirectedinteractionswithsetrequest();
            hla4("unpublishObjectClassDirectedInteractions")
                .unpublishObjectClassDirectedInteractions(object_class(m.objectclass()), interaction_classes(m.interactionclasses()));
            r.mutable_unpublishobjectclassdirectedinteractionswithsetresponse();
            return;
        }
        case C::kSubscribeObjectClassDirectedInteractionsRequest: {
            auto const& m = q.subscribeobjectclassdirectedinteractionsrequest();
            hla4("subscribeObjectClassDirectedInteractions")
                .subscribeObjectClassDirectedInteractions(object_class(m.objectclass()), interaction_classes(m.interactionclasses()), false);
            r.mutable_subscribeobjectclassdirectedinteractionsresponse();
            return;
        }
        case C::kSubscribeObjectClassDirectedInteractionsUniversallyRequest: {
            auto const& m = q.subscribeobjectclassdirectedinteractionsuniversallyrequest();
            hla4("subscribeObjectClassDirectedInteractionsUniversally")
                .subscribeObjectClassDirectedInteractions(object_class(m.objectclass()), interaction_classes(m.interactionclasses()), true);
            r.mutable_subscribeobjectclassdirectedinteractionsuniversallyresponse();
            return;
        }
        case C::kUnsubscribeObjectClassDirectedInteractionsRequest:
            hla4("unsubscribeObjectClassDirectedInteractions")
                .unsubscribeObjectClassDirectedInteractions(object_class(q.unsubscribeobjectclassdirectedinteractionsrequest().objectclass()));
            r.mutable_unsubscribeobjectclassdirectedinteractionsresponse();
            return;
        case C::kUnsubscribeObjectClassDirectedInteractionsWithSetRequest: {
            auto const& m = q.unsubscribeobjectclassdirectedinteractionswithsetrequest();
            hla4("unsubscribeObjectClassDirectedInteractions")
                .unsubscribeObjectClassDirectedInteractions(object_class(m.objectclass()), interaction_classes(m.interactionclasses()));
            r.mutable_unsubscribeobjectclassdirectedinteractionswithsetresponse();
            return;
        }

        // ---- object management ----
        case C::kReserveObjectInstanceNameRequest:
            rti_->reserveObjectInstanceName(wide(q.reserveobjectinstancenamerequest().objectinstancename()));
            r.mutable_reserveobjectinstancenameresponse();
            return;
        case C::kReleaseObjectInstanceNameRequest:
            rti_->releaseObjectInstanceName(wide(q.releaseobjectinstancenamerequest().objectinstancename()));
            r.mutable_releaseobjectinstancenameresponse();
            return;
        case C::kReserveMultipleObjectInstanceNamesRequest: {
            std::set<std::wstring> names;
            for (auto const& n : q.reservemultipleobjectinstancenamesrequest().objectinstancenames()) names.insert(wide(n));
            rti_->reserveMultipleObjectInstanceName(names);
            r.mutable_reservemultipleobjectinstancenamesresponse();
            return;
        }
        case C::kReleaseMultipleObjectInstanceNamesRequest: {
            std::set<std::wstring> names;
            for (auto const& n : q.releasemultipleobjectinstancenamesrequest().objectinstancenames()) names.insert(wide(n));
            rti_->releaseMultipleObjectInstanceName(names);
            r.mutable_releasemultipleobjectinstancenamesresponse();
            return;
        }
        case C::kRegisterObjectInstanceRequest:
            put(r.mutable_registerobjectinstanceresponse()->mutable_result(),
                rti_->registerObjectInstance(object_class(q.registerobjectinstancerequest().objectclass())));
            return;
        case C::kRegisterObjectInstanceWithNameRequest: {
            auto const& m = q.registerobjectinstancewithnamerequest();
            put(r.mutable_registerobjectinstancewithnameresponse()->mutable_result(),
                rti_->registerObjectInstance(object_class(m.objectclass()), wide(m.objectinstancename())));
            return;
        }
        case C::kUpdateAttributeValuesRequest: {
            auto const& m = q.updateattributevaluesrequest();
            rti_->updateAttributeValues(object(m.objectinstance()), values(m.attributevalues()), tag(m.usersuppliedtag()));
            r.mutable_updateattributevaluesresponse();
            return;
        }
        case C::kUpdateAttributeValuesWithTimeRequest: {
            auto const& m = q.updateattributevalueswithtimerequest();
            auto* out = r.mutable_updateattributevalueswithtimeresponse()->mutable_result();
            put(out->mutable_messageretractionhandle(),
                rti_->updateAttributeValues(object(m.objectinstance()), values(m.attributevalues()), tag(m.usersuppliedtag()), *time(m.time())));
            out->set_retractionhandleisvalid(true);
            return;
        }
        case C::kSendInteractionRequest: {
            auto const& m = q.sendinteractionrequest();
            rti_->sendInteraction(interaction_class(m.interactionclass()), values(m.parametervalues()), tag(m.usersuppliedtag()));
            r.mutable_sendinteractionresponse();
            return;
        }
        case C::kSendDirectedInteractionRequest: {
            auto const& m = q.senddirectedinteractionrequest();
            hla4("sendDirectedInteraction")
                .sendDirectedInteraction(interaction_class(m.interactionclass()), object(m.objectinstance()),
                                         values(m.parametervalues()), tag(m.usersuppliedtag()));
            r.mutable_senddirectedinteractionresponse();
            return;
        }
        case C::kSendDirectedInteractionWithTimeRequest: {
            auto const& m = q.senddirectedinteractionwithtimerequest();
            auto* out = r.mutable_senddirectedinteractionwithtimeresponse()->mutable_result();
            put(out->mutable_messageretractionhandle(),
                hla4("sendDirectedInteraction")
                    .sendDirectedInteraction(interaction_class(m.interactionclass()), object(m.objectinstance()),
                                             values(m.parametervalues()), tag(m.usersuppliedtag()), *time(m.time())));
            out->set_retractionhandleisvalid(true);
            return;
        }
        case C::kSendInteractionWithTimeRequest: {
            auto const& m = q.sendinteractionwithtimerequest();
            auto* out = r.mutable_sendinteractionwithtimeresponse()->mutable_result();
            put(out->mutable_messageretractionhandle(),
                rti_->sendInteraction(interaction_class(m.interactionclass()), values(m.parametervalues()), tag(m.usersuppliedtag()),
                                      *time(m.time())));
            out->set_retractionhandleisvalid(true);
            return;
        }
        case C::kDeleteObjectInstanceRequest: {
            auto const& m = q.deleteobjectinstancerequest();
            rti_->deleteObjectInstance(object(m.objectinstance()), tag(m.usersuppliedtag()));
            r.mutable_deleteobjectinstanceresponse();
            return;
        }
        case C::kDeleteObjectInstanceWithTimeRequest: {
            auto const& m = q.deleteobjectinstancewithtimerequest();
            auto* out = r.mutable_deleteobjectinstancewithtimeresponse()->mutable_result();
            put(out->mutable_messageretractionhandle(),
                rti_->deleteObjectInstance(object(m.objectinstance()), tag(m.usersuppliedtag()), *time(m.time())));
            out->set_retractionhandleisvalid(true);
            return;
        }
        case C::kLocalDeleteObjectInstanceRequest:
            rti_->localDeleteObjectInstance(object(q.localdeleteobjectinstancerequest().objectinstance()));
            r.mutable_localdeleteobjectinstanceresponse();
            return;
        case C::kRequestInstanceAttributeValueUpdateRequest: {
            auto const& m = q.requestinstanceattributevalueupdaterequest();
            rti_->requestAttributeValueUpdate(object(m.objectinstance()), attributes(m.attributes()), tag(m.usersuppliedtag()));
            r.mutable_requestinstanceattributevalueupdateresponse();
            return;
        }
        case C::kRequestClassAttributeValueUpdateRequest: {
            auto const& m = q.requestclassattributevalueupdaterequest();
            rti_->requestAttributeValueUpdate(object_class(m.objectclass()), attributes(m.attributes()), tag(m.usersuppliedtag()));
            r.mutable_requestclassattributevalueupdateresponse();
            return;
        }
        case C::kRequestAttributeTransportationTypeChangeRequest: {
            auto const& m = q.requestattributetransportationtypechangerequest();
            rti_->requestAttributeTransportationTypeChange(object(m.objectinstance()), attributes(m.attributes()),
                                                           transportation(m.transportationtype()));
            r.mutable_requestattributetransportationtypechangeresponse();
            return;
        }
        case C::kChangeDefaultAttributeTransportationTypeRequest:
            not_served("changeDefaultAttributeTransportationType", "an HLA 4 service the core does not have yet");
        case C::kQueryAttributeTransportationTypeRequest: {
            auto const& m = q.queryattributetransportationtyperequest();
            rti_->queryAttributeTransportationType(object(m.objectinstance()), attribute(m.attribute()));
            r.mutable_queryattributetransportationtyperesponse();
            return;
        }
        case C::kRequestInteractionTransportationTypeChangeRequest: {
            auto const& m = q.requestinteractiontransportationtypechangerequest();
            rti_->requestInteractionTransportationTypeChange(interaction_class(m.interactionclass()), transportation(m.transportationtype()));
            r.mutable_requestinteractiontransportationtypechangeresponse();
            return;
        }
        case C::kQueryInteractionTransportationTypeRequest: {
            auto const& m = q.queryinteractiontransportationtyperequest();
            rti_->queryInteractionTransportationType(federate(m.federate()), interaction_class(m.interactionclass()));
            r.mutable_queryinteractiontransportationtyperesponse();
            return;
        }

        // ---- ownership management ----
        case C::kUnconditionalAttributeOwnershipDivestitureRequest: {
            auto const& m = q.unconditionalattributeownershipdivestiturerequest();
            rti_->unconditionalAttributeOwnershipDivestiture(object(m.objectinstance()), attributes(m.attributes()));
            r.mutable_unconditionalattributeownershipdivestitureresponse();
            return;
        }
        case C::kNegotiatedAttributeOwnershipDivestitureRequest: {
            auto const& m = q.negotiatedattributeownershipdivestiturerequest();
            rti_->negotiatedAttributeOwnershipDivestiture(object(m.objectinstance()), attributes(m.attributes()), tag(m.usersuppliedtag()));
            r.mutable_negotiatedattributeownershipdivestitureresponse();
            return;
        }
        case C::kConfirmDivestitureRequest: {
            auto const& m = q.confirmdivestiturerequest();
            rti_->confirmDivestiture(object(m.objectinstance()), attributes(m.confirmedattributes()), tag(m.usersuppliedtag()));
            r.mutable_confirmdivestitureresponse();
            return;
        }
        case C::kAttributeOwnershipAcquisitionRequest: {
            auto const& m = q.attributeownershipacquisitionrequest();
            rti_->attributeOwnershipAcquisition(object(m.objectinstance()), attributes(m.desiredattributes()), tag(m.usersuppliedtag()));
            r.mutable_attributeownershipacquisitionresponse();
            return;
        }
        case C::kAttributeOwnershipAcquisitionIfAvailableRequest: {
            auto const& m = q.attributeownershipacquisitionifavailablerequest();
            rti_->attributeOwnershipAcquisitionIfAvailable(object(m.objectinstance()), attributes(m.desiredattributes()));
            r.mutable_attributeownershipacquisitionifavailableresponse();
            return;
        }
        case C::kAttributeOwnershipReleaseDeniedRequest: {
            auto const& m = q.attributeownershipreleasedeniedrequest();
            rti_->attributeOwnershipReleaseDenied(object(m.objectinstance()), attributes(m.attributes()));
            r.mutable_attributeownershipreleasedeniedresponse();
            return;
        }
        case C::kAttributeOwnershipDivestitureIfWantedRequest: {
            auto const& m = q.attributeownershipdivestitureifwantedrequest();
            api::AttributeHandleSet divested;
            rti_->attributeOwnershipDivestitureIfWanted(object(m.objectinstance()), attributes(m.attributes()), divested);
            put(r.mutable_attributeownershipdivestitureifwantedresponse()->mutable_result(), divested);
            return;
        }
        case C::kCancelNegotiatedAttributeOwnershipDivestitureRequest: {
            auto const& m = q.cancelnegotiatedattributeownershipdivestiturerequest();
            rti_->cancelNegotiatedAttributeOwnershipDivestiture(object(m.objectinstance()), attributes(m.attributes()));
            r.mutable_cancelnegotiatedattributeownershipdivestitureresponse();
            return;
        }
        case C::kCancelAttributeOwnershipAcquisitionRequest: {
            auto const& m = q.cancelattributeownershipacquisitionrequest();
            rti_->cancelAttributeOwnershipAcquisition(object(m.objectinstance()), attributes(m.attributes()));
            r.mutable_cancelattributeownershipacquisitionresponse();
            return;
        }
        case C::kQueryAttributeOwnershipRequest: {
            auto const& m = q.queryattributeownershiprequest();
            const api::ObjectInstanceHandle o = object(m.objectinstance());
            for (auto const& a : attributes(m.attributes())) rti_->queryAttributeOwnership(o, a);
            r.mutable_queryattributeownershipresponse();
            return;
        }
        case C::kIsAttributeOwnedByFederateRequest: {
            auto const& m = q.isattributeownedbyfederaterequest();
            r.mutable_isattributeownedbyfederateresponse()->set_result(
                rti_->isAttributeOwnedByFederate(object(m.objectinstance()), attribute(m.attribute())));
            return;
        }

        // ---- time management ----
        case C::kEnableTimeRegulationRequest:
            rti_->enableTimeRegulation(*interval(q.enabletimeregulationrequest().lookahead()));
            r.mutable_enabletimeregulationresponse();
            return;
        case C::kDisableTimeRegulationRequest:
            rti_->disableTimeRegulation();
            r.mutable_disabletimeregulationresponse();
            return;
        case C::kEnableTimeConstrainedRequest:
            rti_->enableTimeConstrained();
            r.mutable_enabletimeconstrainedresponse();
            return;
        case C::kDisableTimeConstrainedRequest:
            rti_->disableTimeConstrained();
            r.mutable_disabletimeconstrainedresponse();
            return;
        case C::kTimeAdvanceRequestRequest:
            rti_->timeAdvanceRequest(*time(q.timeadvancerequestrequest().time()));
            r.mutable_timeadvancerequestresponse();
            return;
        case C::kTimeAdvanceRequestAvailableRequest:
            rti_->timeAdvanceRequestAvailable(*time(q.timeadvancerequestavailablerequest().time()));
            r.mutable_timeadvancerequestavailableresponse();
            return;
        case C::kNextMessageRequestRequest:
            rti_->nextMessageRequest(*time(q.nextmessagerequestrequest().time()));
            r.mutable_nextmessagerequestresponse();
            return;
        case C::kNextMessageRequestAvailableRequest:
            rti_->nextMessageRequestAvailable(*time(q.nextmessagerequestavailablerequest().time()));
            r.mutable_nextmessagerequestavailableresponse();
            return;
        case C::kFlushQueueRequestRequest:
            rti_->flushQueueRequest(*time(q.flushqueuerequestrequest().time()));
            r.mutable_flushqueuerequestresponse();
            return;
        case C::kEnableAsynchronousDeliveryRequest:
            rti_->enableAsynchronousDelivery();
            r.mutable_enableasynchronousdeliveryresponse();
            return;
        case C::kDisableAsynchronousDeliveryRequest:
            rti_->disableAsynchronousDelivery();
            r.mutable_disableasynchronousdeliveryresponse();
            return;
        case C::kQueryGALTRequest: {
            auto t = factory().makeInitial();
            auto* out = r.mutable_querygaltresponse()->mutable_result();
            out->set_logicaltimeisvalid(rti_->queryGALT(*t));
            if (out->logicaltimeisvalid()) put(out->mutable_logicaltime(), *t);
            return;
        }
        case C::kQueryLogicalTimeRequest: {
            auto t = factory().makeInitial();
            rti_->queryLogicalTime(*t);
            put(r.mutable_querylogicaltimeresponse()->mutable_result(), *t);
            return;
        }
        case C::kQueryLITSRequest: {
            auto t = factory().makeInitial();
            auto* out = r.mutable_querylitsresponse()->mutable_result();
            out->set_logicaltimeisvalid(rti_->queryLITS(*t));
            if (out->logicaltimeisvalid()) put(out->mutable_logicaltime(), *t);
            return;
        }
        case C::kModifyLookaheadRequest:
            rti_->modifyLookahead(*interval(q.modifylookaheadrequest().lookahead()));
            r.mutable_modifylookaheadresponse();
            return;
        case C::kQueryLookaheadRequest: {
            auto l = factory().makeZero();
            rti_->queryLookahead(*l);
            put(r.mutable_querylookaheadresponse()->mutable_result(), *l);
            return;
        }
        case C::kRetractRequest:
            rti_->retract(retraction(q.retractrequest().retraction()));
            r.mutable_retractresponse();
            return;
        case C::kChangeAttributeOrderTypeRequest: {
            auto const& m = q.changeattributeordertyperequest();
            rti_->changeAttributeOrderType(object(m.objectinstance()), attributes(m.attributes()), order(m.ordertype()));
            r.mutable_changeattributeordertyperesponse();
            return;
        }
        case C::kChangeDefaultAttributeOrderTypeRequest:
            not_served("changeDefaultAttributeOrderType", "an HLA 4 service the core does not have yet");
        case C::kChangeInteractionOrderTypeRequest: {
            auto const& m = q.changeinteractionordertyperequest();
            rti_->changeInteractionOrderType(interaction_class(m.interactionclass()), order(m.ordertype()));
            r.mutable_changeinteractionordertyperesponse();
            return;
        }

        // ---- data distribution management ----
        case C::kCreateRegionRequest:
            put(r.mutable_createregionresponse()->mutable_result(), rti_->createRegion(dimensions(q.createregionrequest().dimensions())));
            return;
        case C::kCommitRegionModificationsRequest:
            rti_->commitRegionModifications(regions(q.commitregionmodificationsrequest().regions()));
            r.mutable_commitregionmodificationsresponse();
            return;
        case C::kDeleteRegionRequest:
            rti_->deleteRegion(region(q.deleteregionrequest().region()));
            r.mutable_deleteregionresponse();
            return;
        case C::kRegisterObjectInstanceWithRegionsRequest: {
            auto const& m = q.registerobjectinstancewithregionsrequest();
            put(r.mutable_registerobjectinstancewithregionsresponse()->mutable_result(),
                rti_->registerObjectInstanceWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions())));
            return;
        }
        case C::kRegisterObjectInstanceWithNameAndRegionsRequest: {
            auto const& m = q.registerobjectinstancewithnameandregionsrequest();
            put(r.mutable_registerobjectinstancewithnameandregionsresponse()->mutable_result(),
                rti_->registerObjectInstanceWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions()),
                                                        wide(m.objectinstancename())));
            return;
        }
        case C::kAssociateRegionsForUpdatesRequest: {
            auto const& m = q.associateregionsforupdatesrequest();
            rti_->associateRegionsForUpdates(object(m.objectinstance()), pairs(m.attributesandregions()));
            r.mutable_associateregionsforupdatesresponse();
            return;
        }
        case C::kUnassociateRegionsForUpdatesRequest: {
            auto const& m = q.unassociateregionsforupdatesrequest();
            rti_->unassociateRegionsForUpdates(object(m.objectinstance()), pairs(m.attributesandregions()));
            r.mutable_unassociateregionsforupdatesresponse();
            return;
        }
        case C::kSubscribeObjectClassAttributesWithRegionsRequest: {
            auto const& m = q.subscribeobjectclassattributeswithregionsrequest();
            rti_->subscribeObjectClassAttributesWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions()), m.active());
            r.mutable_subscribeobjectclassattributeswithregionsresponse();
            return;
        }
        case C::kSubscribeObjectClassAttributesWithRegionsAndRateRequest: {
            auto const& m = q.subscribeobjectclassattributeswithregionsandraterequest();
            rti_->subscribeObjectClassAttributesWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions()), m.active(),
                                                            wide(m.updateratedesignator()));
            r.mutable_subscribeobjectclassattributeswithregionsandrateresponse();
            return;
        }
        case C::kUnsubscribeObjectClassAttributesWithRegionsRequest: {
            auto const& m = q.unsubscribeobjectclassattributeswithregionsrequest();
            rti_->unsubscribeObjectClassAttributesWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions()));
            r.mutable_unsubscribeobjectclassattributeswithregionsresponse();
            return;
        }
        case C::kSubscribeInteractionClassWithRegionsRequest: {
            auto const& m = q.subscribeinteractionclasswithregionsrequest();
            rti_->subscribeInteractionClassWithRegions(interaction_class(m.interactionclass()), regions(m.regions()), m.active());
            r.mutable_subscribeinteractionclasswithregionsresponse();
            return;
        }
        case C::kUnsubscribeInteractionClassWithRegionsRequest: {
            auto const& m = q.unsubscribeinteractionclasswithregionsrequest();
            rti_->unsubscribeInteractionClassWithRegions(interaction_class(m.interactionclass()), regions(m.regions()));
            r.mutable_unsubscribeinteractionclasswithregionsresponse();
            return;
        }
        case C::kSendInteractionWithRegionsRequest: {
            auto const& m = q.sendinteractionwithregionsrequest();
            rti_->sendInteractionWithRegions(interaction_class(m.interactionclass()), values(m.parametervalues()), regions(m.regions()),
                                             tag(m.usersuppliedtag()));
            r.mutable_sendinteractionwithregionsresponse();
            return;
        }
        case C::kSendInteractionWithRegionsAndTimeRequest: {
            auto const& m = q.sendinteractionwithregionsandtimerequest();
            auto* out = r.mutable_sendinteractionwithregionsandtimeresponse()->mutable_result();
            put(out->mutable_messageretractionhandle(),
                rti_->sendInteractionWithRegions(interaction_class(m.interactionclass()), values(m.parametervalues()),
                                                 regions(m.regions()), tag(m.usersuppliedtag()), *time(m.time())));
            out->set_retractionhandleisvalid(true);
            return;
        }
        case C::kRequestAttributeValueUpdateWithRegionsRequest: {
            auto const& m = q.requestattributevalueupdatewithregionsrequest();
            rti_->requestAttributeValueUpdateWithRegions(object_class(m.objectclass()), pairs(m.attributesandregions()),
                                                         tag(m.usersuppliedtag()));
            r.mutable_requestattributevalueupdatewithregionsresponse();
            return;
        }

        // ---- support services ----
        case C::kGetFederateHandleRequest:
            put(r.mutable_getfederatehandleresponse()->mutable_result(),
                rti_->getFederateHandle(wide(q.getfederatehandlerequest().federatename())));
            return;
        case C::kGetFederateNameRequest:
            r.mutable_getfederatenameresponse()->set_result(utf8(rti_->getFederateName(federate(q.getfederatenamerequest().federate()))));
            return;
        case C::kGetObjectClassHandleRequest:
            put(r.mutable_getobjectclasshandleresponse()->mutable_result(),
                rti_->getObjectClassHandle(wide(q.getobjectclasshandlerequest().objectclassname())));
            return;
        case C::kGetObjectClassNameRequest:
            r.mutable_getobjectclassnameresponse()->set_result(
                utf8(rti_->getObjectClassName(object_class(q.getobjectclassnamerequest().objectclass()))));
            return;
        case C::kGetKnownObjectClassHandleRequest:
            put(r.mutable_getknownobjectclasshandleresponse()->mutable_result(),
                rti_->getKnownObjectClassHandle(object(q.getknownobjectclasshandlerequest().objectinstance())));
            return;
        case C::kGetObjectInstanceHandleRequest:
            put(r.mutable_getobjectinstancehandleresponse()->mutable_result(),
                rti_->getObjectInstanceHandle(wide(q.getobjectinstancehandlerequest().objectinstancename())));
            return;
        case C::kGetObjectInstanceNameRequest:
            r.mutable_getobjectinstancenameresponse()->set_result(
                utf8(rti_->getObjectInstanceName(object(q.getobjectinstancenamerequest().objectinstance()))));
            return;
        case C::kGetAttributeHandleRequest: {
            auto const& m = q.getattributehandlerequest();
            put(r.mutable_getattributehandleresponse()->mutable_result(),
                rti_->getAttributeHandle(object_class(m.objectclass()), wide(m.attributename())));
            return;
        }
        case C::kGetAttributeNameRequest: {
            auto const& m = q.getattributenamerequest();
            r.mutable_getattributenameresponse()->set_result(utf8(rti_->getAttributeName(object_class(m.objectclass()), attribute(m.attribute()))));
            return;
        }
        case C::kGetUpdateRateValueRequest:
            r.mutable_getupdateratevalueresponse()->set_result(
                rti_->getUpdateRateValue(wide(q.getupdateratevaluerequest().updateratedesignator())));
            return;
        case C::kGetUpdateRateValueForAttributeRequest: {
            auto const& m = q.getupdateratevalueforattributerequest();
            r.mutable_getupdateratevalueforattributeresponse()->set_result(
                rti_->getUpdateRateValueForAttribute(object(m.objectinstance()), attribute(m.attribute())));
            return;
        }
        case C::kGetInteractionClassHandleRequest:
            put(r.mutable_getinteractionclasshandleresponse()->mutable_result(),
                rti_->getInteractionClassHandle(wide(q.getinteractionclasshandlerequest().interactionclassname())));
            return;
        case C::kGetInteractionClassNameRequest:
            r.mutable_getinteractionclassnameresponse()->set_result(
                utf8(rti_->getInteractionClassName(interaction_class(q.getinteractionclassnamerequest().interactionclass()))));
            return;
        case C::kGetParameterHandleRequest: {
            auto const& m = q.getparameterhandlerequest();
            put(r.mutable_getparameterhandleresponse()->mutable_result(),
                rti_->getParameterHandle(interaction_class(m.interactionclass()), wide(m.parametername())));
            return;
        }
        case C::kGetParameterNameRequest: {
            auto const& m = q.getparameternamerequest();
            r.mutable_getparameternameresponse()->set_result(
                utf8(rti_->getParameterName(interaction_class(m.interactionclass()), parameter(m.parameter()))));
            return;
        }
        case C::kGetOrderTypeRequest:
            r.mutable_getordertyperesponse()->set_result(order(rti_->getOrderType(wide(q.getordertyperequest().ordertypename()))));
            return;
        case C::kGetOrderNameRequest:
            r.mutable_getordernameresponse()->set_result(utf8(rti_->getOrderName(order(q.getordernamerequest().ordertype()))));
            return;
        case C::kGetTransportationTypeHandleRequest:
            put(r.mutable_gettransportationtypehandleresponse()->mutable_result(),
                rti_->getTransportationType(wide(q.gettransportationtypehandlerequest().transportationtypename())));
            return;
        case C::kGetTransportationTypeNameRequest:
            r.mutable_gettransportationtypenameresponse()->set_result(
                utf8(rti_->getTransportationName(transportation(q.gettransportationtypenamerequest().transportationtype()))));
            return;
        case C::kGetAvailableDimensionsForObjectClassRequest:
            put(r.mutable_getavailabledimensionsforobjectclassresponse()->mutable_result(),
                hla4("getAvailableDimensionsForObjectClass")
                    .availableDimensionsForObjectClass(object_class(q.getavailabledimensionsforobjectclassrequest().objectclass())));
            return;
        case C::kGetAvailableDimensionsForInteractionClassRequest:
            put(r.mutable_getavailabledimensionsforinteractionclassresponse()->mutable_result(),
                rti_->getAvailableDimensionsForInteractionClass(
                    interaction_class(q.getavailabledimensionsforinteractionclassrequest().interactionclass())));
            return;
        case C::kGetDimensionHandleRequest:
            put(r.mutable_getdimensionhandleresponse()->mutable_result(),
                rti_->getDimensionHandle(wide(q.getdimensionhandlerequest().dimensionname())));
            return;
        case C::kGetDimensionNameRequest:
            r.mutable_getdimensionnameresponse()->set_result(utf8(rti_->getDimensionName(dimension(q.getdimensionnamerequest().dimension()))));
            return;
        case C::kGetDimensionUpperBoundRequest:
            r.mutable_getdimensionupperboundresponse()->set_result(
                std::uint32_t(rti_->getDimensionUpperBound(dimension(q.getdimensionupperboundrequest().dimension()))));
            return;
        case C::kGetDimensionHandleSetRequest:
            put(r.mutable_getdimensionhandlesetresponse()->mutable_result(),
                rti_->getDimensionHandleSet(region(q.getdimensionhandlesetrequest().region())));
            return;
        case C::kGetRangeBoundsRequest: {
            auto const& m = q.getrangeboundsrequest();
            const api::RangeBounds b = rti_->getRangeBounds(region(m.region()), dimension(m.dimension()));
            auto* out = r.mutable_getrangeboundsresponse()->mutable_result();
            out->set_lower(std::uint32_t(b.getLowerBound()));
            out->set_upper(std::uint32_t(b.getUpperBound()));
            return;
        }
        case C::kSetRangeBoundsRequest: {
            auto const& m = q.setrangeboundsrequest();
            rti_->setRangeBounds(region(m.region()), dimension(m.dimension()),
                                 api::RangeBounds(m.rangebounds().lower(), m.rangebounds().upper()));
            r.mutable_setrangeboundsresponse();
            return;
        }
        case C::kNormalizeServiceGroupRequest:
            r.mutable_normalizeservicegroupresponse()->set_result(std::uint32_t(
                rti_->normalizeServiceGroup(static_cast<api::ServiceGroup>(q.normalizeservicegrouprequest().servicegroup()))));
            return;
        case C::kNormalizeFederateHandleRequest:
            r.mutable_normalizefederatehandleresponse()->set_result(
                std::uint32_t(rti_->normalizeFederateHandle(federate(q.normalizefederatehandlerequest().federate()))));
            return;
        case C::kNormalizeObjectClassHandleRequest:
        case C::kNormalizeInteractionClassHandleRequest:
        case C::kNormalizeObjectInstanceHandleRequest:
            not_served("normalizing class and instance handles", "an HLA 4 service the core does not have yet");
        case C::kSetObjectClassRelevanceAdvisorySwitchRequest: {
            const bool on = q.setobjectclassrelevanceadvisoryswitchrequest().value();
            on ? rti_->enableObjectClassRelevanceAdvisorySwitch() : rti_->disableObjectClassRelevanceAdvisorySwitch();
            class_relevance_ = on;
            r.mutable_setobjectclassrelevanceadvisoryswitchresponse();
            return;
        }
        case C::kSetAttributeRelevanceAdvisorySwitchRequest: {
            const bool on = q.setattributerelevanceadvisoryswitchrequest().value();
            on ? rti_->enableAttributeRelevanceAdvisorySwitch() : rti_->disableAttributeRelevanceAdvisorySwitch();
            attribute_relevance_ = on;
            r.mutable_setattributerelevanceadvisoryswitchresponse();
            return;
        }
        case C::kSetAttributeScopeAdvisorySwitchRequest: {
            const bool on = q.setattributescopeadvisoryswitchrequest().value();
            on ? rti_->enableAttributeScopeAdvisorySwitch() : rti_->disableAttributeScopeAdvisorySwitch();
            attribute_scope_ = on;
            r.mutable_setattributescopeadvisoryswitchresponse();
            return;
        }
        case C::kSetInteractionRelevanceAdvisorySwitchRequest: {
            const bool on = q.setinteractionrelevanceadvisoryswitchrequest().value();
            on ? rti_->enableInteractionRelevanceAdvisorySwitch() : rti_->disableInteractionRelevanceAdvisorySwitch();
            interaction_relevance_ = on;
            r.mutable_setinteractionrelevanceadvisoryswitchresponse();
            return;
        }
        case C::kGetObjectClassRelevanceAdvisorySwitchRequest:
            r.mutable_getobjectclassrelevanceadvisoryswitchresponse()->set_result(class_relevance_);
            return;
        case C::kGetAttributeRelevanceAdvisorySwitchRequest:
            r.mutable_getattributerelevanceadvisoryswitchresponse()->set_result(attribute_relevance_);
            return;
        case C::kGetAttributeScopeAdvisorySwitchRequest:
            r.mutable_getattributescopeadvisoryswitchresponse()->set_result(attribute_scope_);
            return;
        case C::kGetInteractionRelevanceAdvisorySwitchRequest:
            r.mutable_getinteractionrelevanceadvisoryswitchresponse()->set_result(interaction_relevance_);
            return;
        case C::kGetAutomaticResignDirectiveRequest:
            r.mutable_getautomaticresigndirectiveresponse()->set_result(static_cast<pb::ResignAction>(rti_->getAutomaticResignDirective()));
            return;
        case C::kSetAutomaticResignDirectiveRequest:
            rti_->setAutomaticResignDirective(static_cast<api::ResignAction>(q.setautomaticresigndirectiverequest().value()));
            r.mutable_setautomaticresigndirectiveresponse();
            return;
        case C::kListFederationExecutionMembersRequest:
            list_members(q.listfederationexecutionmembersrequest().federationname());
            r.mutable_listfederationexecutionmembersresponse();
            return;
        case C::kGetConveyRegionDesignatorSetsSwitchRequest:
        case C::kSetConveyRegionDesignatorSetsSwitchRequest:
        case C::kGetServiceReportingSwitchRequest:
        case C::kSetServiceReportingSwitchRequest:
        case C::kGetExceptionReportingSwitchRequest:
        case C::kSetExceptionReportingSwitchRequest:
        case C::kGetSendServiceReportsToFileSwitchRequest:
        case C::kSetSendServiceReportsToFileSwitchRequest:
        case C::kGetAutoProvideSwitchRequest:
        case C::kGetDelaySubscriptionEvaluationSwitchRequest:
        case C::kGetAdvisoriesUseKnownClassSwitchRequest:
        case C::kGetAllowRelaxedDDMSwitchRequest:
        case C::kGetNonRegulatedGrantSwitchRequest:
            not_served(pb::CallRequest::descriptor()->FindFieldByNumber(q.callRequest_case())->name().c_str(),
                       "an HLA 4 service or switch the core does not have yet");
        case C::CALLREQUEST_NOT_SET:
            break;
    }
    throw api::RTIinternalError(L"RTIinternalError: a call request that names no call");
}

void HlaFederate::declared(pb::RtiConfiguration const& configuration) {
    api_2010_ = configuration.additionalsettings().find("API.version=IEEE 1516-2010") != std::string::npos;
}

void HlaFederate::connect(pb::Credentials const* credentials) {
    if (!password_.empty()) {
        if (credentials && credentials->type() != kPlainTextPassword && credentials->type() != "HLAnoCredentials")
            throw Hla4Exception("InvalidCredentials", "credentials of type '" + credentials->type() +
                                                          "', which this RTI does not read (HLAplainTextPassword)");
        if (!credentials || credentials->type() != kPlainTextPassword)
            throw Hla4Exception("Unauthorized", "this RTI lets in federates with HLAplainTextPassword credentials only: the "
                                                "gateway's secret (docs/fedpro.md)");
        if (!same_secret(password(credentials->data()), password_))
            throw Hla4Exception("Unauthorized", "the password is not the gateway's secret");
    }
    rti_->connect(*this, api::HLA_IMMEDIATE, wide(gateway_));
}

void HlaFederate::joined(api::FederateHandle const& handle, std::string const& federation, pb::JoinResult* result) {
    joined_ = true;
    std::string name = utf8(rti_->getFederateName(handle));  // asks the gateway, which may be asking member()
    {
        std::lock_guard<std::mutex> lock(member_mutex_);
        member_ = {federation, std::move(name)};
    }
    class_relevance_ = interaction_relevance_ = true;  // a join starts from the core's defaults
    attribute_relevance_ = attribute_scope_ = false;
    factory_ = rti_->getTimeFactory();
    put(result->mutable_federatehandle(), handle);
    result->set_logicaltimeimplementationname(utf8(factory_->getName()));
}

rti1516e::Ambassador& HlaFederate::hla4(const char* service) const {
    auto* ours = dynamic_cast<rti1516e::Ambassador*>(rti_.get());
    if (!ours) not_served(service, "the session's ambassador is not hlacore's");
    return *ours;
}

// HLA 4's answer is a callback: the members as the gateway's report has them (their types as they joined), or
// that there is no such federation.
void HlaFederate::list_members(std::string const& federation) {
    std::vector<std::pair<std::wstring, std::wstring>> members;
    if (!hla4("listFederationExecutionMembers").federationMembers(wide(federation), members)) {
        HLACORE_FEDPRO_CALLBACK(reportfederationexecutiondoesnotexist, m->set_federationname(federation));
        return;
    }
    HLACORE_FEDPRO_CALLBACK(reportfederationexecutionmembers, {
        m->set_federationname(federation);
        for (auto const& [name, type] : members) {
            auto* info = m->mutable_report()->add_federationexecutionmemberinformation();
            info->set_federatename(utf8(name));
            info->set_federatetype(utf8(type));
        }
    });
}

void HlaFederate::left() {
    joined_ = false;
    std::lock_guard<std::mutex> lock(member_mutex_);
    member_ = {};
}

std::pair<std::string, std::string> HlaFederate::member() const {
    std::lock_guard<std::mutex> lock(member_mutex_);
    return member_;
}

}  // namespace hlacore::fedpro
