// The federate's requests: each CERTI message as the call of hlacore's client, and the answer CERTI's libRTI
// reads from it (the same type; a handle, a name, a date or a retraction where the service returns one).
#include <unistd.h>

#include <algorithm>

#include "certi/rtia.hpp"
#include "fed_parser/omt.hpp"

namespace hlacore::certi {

namespace {

std::string tag_of(const Message& m) { return m.tag.value_or(std::string()); }
std::string label_of(const Message& m) { return m.label.value_or(std::string()); }

// A timestamped message's answer: its date and the retraction handle of what was sent.
void retractable(Message& answer, const Client& c, const Message& request, std::uint64_t serial) {
    if (!request.date) return;
    answer.date = request.date;
    answer.retraction = EventRetraction{c.federate_handle(), serial};
}

// The values of an update or an interaction, as the client takes them (views into the request).
wire::HandleValueViews values_of(const Message& m) {
    if (m.handles.size() != m.values.size())
        raise(ErrorCode::RTIinternalError, std::to_string(m.handles.size()) + " handles for " +
                                               std::to_string(m.values.size()) + " values");
    wire::HandleValueViews views;
    views.reserve(m.handles.size());
    for (std::size_t i = 0; i < m.handles.size(); ++i) views.emplace_back(m.handles[i], m.values[i]);
    return views;
}

[[noreturn]] void unimplemented(const Message& m, const std::string& why) {
    raise(ErrorCode::RTIinternalError, std::string(type_name(m.type)) + ": " + why);
}

// createFederationExecution: the FED file or FOM module found as CERTI finds it, sent to the gateway.
void create(Client& c, const std::string& federation, const std::string& fed) {
    std::string path;
    const std::string text = find_fed(fed, path);
    c.create_federation(federation, path.empty() ? fed : path, text);
}

// A FOM module JCERTI names by URL (file:/path).
std::string file_path(const std::string& module) {
    const std::string scheme = "file:";
    if (module.compare(0, scheme.size(), scheme) != 0) return module;
    std::string path = module.substr(scheme.size());
    while (path.size() > 1 && path[0] == '/' && path[1] == '/') path.erase(0, 1);  // file:///p, file://p
    return path;
}

// Modules, each found here and merged here (errors at the federate's call), as one bundle; `paths` lists them.
std::string bundle_of(const std::vector<std::string>& names, std::string& paths) {
    std::vector<fom::FomModule> modules;
    for (const auto& name : names) {
        std::string path;
        std::string text = find_file(file_path(name), path);  // checked once, merged, below
        if (path.empty()) raise(ErrorCode::CouldNotOpenFED, "FOM module '" + name + "' was not found");
        paths += (paths.empty() ? "" : ", ") + path;
        modules.push_back({std::move(text), path});
    }
    try {
        fom::parse_omt(modules);
    } catch (const fom::FedError& e) {
        raise(ErrorCode::ErrorReadingFED, e.what());
    }
    return fom::bundle(modules);
}

void create_from_modules(Client& c, const std::string& federation, const std::vector<std::string>& names) {
    if (names.empty()) raise(ErrorCode::CouldNotOpenFED, "no FOM module given");
    std::string paths;
    std::string modules = bundle_of(names, paths);
    c.create_federation(federation, paths, modules);
}

wire::AdvisorySwitch switch_of(Type t) {
    switch (t) {
        case Type::ENABLE_CLASS_RELEVANCE_ADVISORY_SWITCH:
        case Type::DISABLE_CLASS_RELEVANCE_ADVISORY_SWITCH: return wire::AdvisorySwitch::ClassRelevance;
        case Type::ENABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH:
        case Type::DISABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH: return wire::AdvisorySwitch::AttributeRelevance;
        case Type::ENABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH:
        case Type::DISABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH: return wire::AdvisorySwitch::AttributeScope;
        default: return wire::AdvisorySwitch::InteractionRelevance;
    }
}

bool enables(Type t) {
    return t == Type::ENABLE_CLASS_RELEVANCE_ADVISORY_SWITCH || t == Type::ENABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH ||
           t == Type::ENABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH || t == Type::ENABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH;
}

}  // namespace

Message Rtia::serve(const Message& q) {
    Message a(q.type);
    if (q.type == Type::OPEN_CONNEXION) {
        if (q.version_major != kVersionMajor)
            raise(ErrorCode::RTIinternalError, "CERTI federate protocol " + std::to_string(q.version_major) + "." +
                                                   std::to_string(q.version_minor) + ", hlacore-rtia speaks " +
                                                   std::to_string(kVersionMajor) + "." + std::to_string(kVersionMinor));
        a.version_major = kVersionMajor;
        a.version_minor = std::min(q.version_minor, kVersionMinor);
        if (!client_) {
            ClientSettings s = client_settings({});
            // Federations created through the rtia keep CERTI's time rules unless $HLACORE_TIME_SEMANTICS says.
            if (s.options.time_semantics == TimeSemantics::Default) s.options.time_semantics = TimeSemantics::Certi;
            client_.emplace(s.host, s.port, std::move(s.options));
        }
        return a;
    }
    if (q.type == Type::CLOSE_CONNEXION) {
        closed_ = true;
        return a;
    }
    Client& c = client();
    switch (q.type) {
        // ---- federation management ----
        case Type::CREATE_FEDERATION_EXECUTION:
            create(c, q.federation_name, q.fed_id);
            break;
        case Type::CREATE_FEDERATION_EXECUTION_V4:  // JCERTI's IEEE 1516-2010 create: FOM modules by path or URL
            if (q.values.size() == 1)
                create(c, q.federation_name, file_path(q.values.front()));
            else
                create_from_modules(c, q.federation_name, q.values);
            break;
        case Type::JOIN_FEDERATION_EXECUTION_V4: {
            // Modules added to the federation's FOM (IEEE 1516-2010 §4.5), as at creation.
            std::string paths;
            const std::string added = q.values.empty() ? "" : bundle_of(q.values, paths);
            // IEEE 1516-2010 lets the RTI name a federate that gives no name: its type and the rtia's pid.
            a.federate = c.join(q.has_name ? q.name : q.federate_type + "-" + std::to_string(::getpid()),
                                q.federation_name, added, q.federate_type);
            joined_ = true;
            break;
        }
        case Type::DESTROY_FEDERATION_EXECUTION:
            c.destroy_federation(q.federation_name);
            a.federation_name = q.federation_name;
            break;
        case Type::JOIN_FEDERATION_EXECUTION:
            a.federate = c.join(q.federate_name, q.federation_name);
            a.federation_name = q.federation_name;
            a.federate_name = q.federate_name;
            joined_ = true;
            break;
        case Type::RESIGN_FEDERATION_EXECUTION:
            c.resign(q.resign_action > 0xFF ? 0 : static_cast<std::uint8_t>(q.resign_action));  // it refuses not 1-4
            joined_ = false;
            break;
        case Type::REGISTER_FEDERATION_SYNCHRONIZATION_POINT:
            c.request(wire::RegisterSyncPoint{label_of(q), tag_of(q), q.handles.empty(), q.handles});
            break;
        case Type::SYNCHRONIZATION_POINT_ACHIEVED: c.request(wire::SyncPointAchieved{label_of(q)}); break;
        case Type::REQUEST_FEDERATION_SAVE:
            c.request_federation_save(label_of(q), q.date);
            a.date = q.date;
            break;
        case Type::FEDERATE_SAVE_BEGUN: c.federate_save_begun(); break;
        case Type::FEDERATE_SAVE_COMPLETE: c.federate_save_complete(true); break;
        case Type::FEDERATE_SAVE_NOT_COMPLETE: c.federate_save_complete(false); break;
        case Type::REQUEST_FEDERATION_RESTORE: c.request_federation_restore(label_of(q)); break;
        case Type::FEDERATE_RESTORE_COMPLETE: c.federate_restore_complete(true); break;
        case Type::FEDERATE_RESTORE_NOT_COMPLETE: c.federate_restore_complete(false); break;

        // ---- declaration management ----
        case Type::PUBLISH_OBJECT_CLASS: c.publish_object_class(q.object_class, q.handles); break;
        case Type::UNPUBLISH_OBJECT_CLASS: c.unpublish_object_class(q.object_class); break;
        case Type::PUBLISH_INTERACTION_CLASS: c.request(wire::PublishInteractionClass{q.interaction_class}); break;
        case Type::UNPUBLISH_INTERACTION_CLASS: c.request(wire::UnpublishInteractionClass{q.interaction_class}); break;
        case Type::SUBSCRIBE_OBJECT_CLASS_ATTRIBUTES:
            c.request(wire::SubscribeObjectClass{q.object_class, q.handles, q.flag});
            break;
        case Type::UNSUBSCRIBE_OBJECT_CLASS: c.request(wire::UnsubscribeObjectClass{q.object_class}); break;
        case Type::SUBSCRIBE_INTERACTION_CLASS: c.request(wire::SubscribeInteractionClass{q.interaction_class, true}); break;
        case Type::UNSUBSCRIBE_INTERACTION_CLASS: c.request(wire::UnsubscribeInteractionClass{q.interaction_class}); break;

        // ---- object management ----
        case Type::REGISTER_OBJECT_INSTANCE:
            a.object = c.register_object(q.object_class, q.has_name ? q.name : std::string());
            break;
        case Type::UPDATE_ATTRIBUTE_VALUES:
            retractable(a, c, q, c.update_attributes(q.object, values_of(q), tag_of(q), q.date));
            break;
        case Type::SEND_INTERACTION:
            if (q.region != 0) unimplemented(q, "interactions with a region (hlacore-rtia serves no DDM yet)");
            retractable(a, c, q, c.send_interaction(q.interaction_class, values_of(q), tag_of(q), q.date));
            break;
        case Type::DELETE_OBJECT_INSTANCE:
            retractable(a, c, q, c.delete_object(q.object, tag_of(q), q.date));
            break;
        case Type::LOCAL_DELETE_OBJECT_INSTANCE: c.request(wire::LocalDeleteObject{q.object}); break;
        case Type::CHANGE_ATTRIBUTE_TRANSPORTATION_TYPE:
            c.change_attribute_transportation(q.object, q.handles, q.transport);
            break;
        case Type::CHANGE_INTERACTION_TRANSPORTATION_TYPE:
            c.change_interaction_transportation(q.interaction_class, q.transport);
            break;
        case Type::CHANGE_ATTRIBUTE_ORDER_TYPE: c.change_attribute_order(q.object, q.handles, q.order); break;
        case Type::CHANGE_INTERACTION_ORDER_TYPE: c.change_interaction_order(q.interaction_class, q.order); break;
        case Type::REQUEST_OBJECT_ATTRIBUTE_VALUE_UPDATE: c.request(wire::RequestObjectUpdate{q.object, q.handles}); break;
        case Type::REQUEST_CLASS_ATTRIBUTE_VALUE_UPDATE:
            c.request(wire::RequestClassUpdate{q.object_class, q.handles});
            break;

        // ---- ownership management ----
        case Type::UNCONDITIONAL_ATTRIBUTE_OWNERSHIP_DIVESTITURE: c.unconditional_divestiture(q.object, q.handles); break;
        case Type::NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE:
            c.negotiated_divestiture(q.object, q.handles, tag_of(q));
            break;
        case Type::ATTRIBUTE_OWNERSHIP_ACQUISITION: c.ownership_acquisition(q.object, q.handles, tag_of(q)); break;
        case Type::ATTRIBUTE_OWNERSHIP_ACQUISITION_IF_AVAILABLE:
            c.ownership_acquisition_if_available(q.object, q.handles);
            break;
        case Type::ATTRIBUTE_OWNERSHIP_RELEASE_RESPONSE:
            a.object = q.object;
            a.handles = c.release_response(q.object, q.handles);
            break;
        case Type::CANCEL_NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE:
            c.request(wire::CancelNegotiatedDivestiture{q.object, q.handles});
            break;
        case Type::CANCEL_ATTRIBUTE_OWNERSHIP_ACQUISITION:
            c.request(wire::CancelOwnershipAcquisition{q.object, q.handles});
            break;
        case Type::QUERY_ATTRIBUTE_OWNERSHIP: c.request(wire::QueryOwnership{q.object, q.attribute}); break;
        case Type::IS_ATTRIBUTE_OWNED_BY_FEDERATE:
            a.tag = c.is_owned(q.object, q.attribute) ? "RTI_TRUE" : "RTI_FALSE";  // CERTI answers in the tag
            break;

        // ---- time management ----
        case Type::ENABLE_TIME_REGULATION: c.enable_time_regulation(q.date.value_or(0.0), q.lookahead); break;
        case Type::DISABLE_TIME_REGULATION: c.disable_time_regulation(); break;
        case Type::ENABLE_TIME_CONSTRAINED: c.enable_time_constrained(); break;
        case Type::DISABLE_TIME_CONSTRAINED: c.disable_time_constrained(); break;
        case Type::QUERY_LBTS: a.date = c.query_lbts(); break;
        case Type::QUERY_FEDERATE_TIME: a.date = c.query_federate_time(); break;
        case Type::QUERY_MIN_NEXT_EVENT_TIME: a.date = c.query_min_next_event_time(); break;
        case Type::MODIFY_LOOKAHEAD:
            c.modify_lookahead(q.lookahead);
            a.lookahead = q.lookahead;
            break;
        case Type::QUERY_LOOKAHEAD: a.lookahead = c.query_lookahead(); break;
        case Type::RETRACT: {
            const EventRetraction r = q.retraction.value_or(EventRetraction{});
            c.retract(r.federate, r.serial);
            break;
        }
        case Type::TIME_ADVANCE_REQUEST: c.time_advance(AdvanceKind::TimeAdvanceRequest, q.date.value_or(0.0)); break;
        case Type::TIME_ADVANCE_REQUEST_AVAILABLE:
            c.time_advance(AdvanceKind::TimeAdvanceRequestAvailable, q.date.value_or(0.0));
            break;
        case Type::NEXT_EVENT_REQUEST: c.time_advance(AdvanceKind::NextEventRequest, q.date.value_or(0.0)); break;
        case Type::NEXT_EVENT_REQUEST_AVAILABLE:
            c.time_advance(AdvanceKind::NextEventRequestAvailable, q.date.value_or(0.0));
            break;
        case Type::FLUSH_QUEUE_REQUEST: c.time_advance(AdvanceKind::FlushQueueRequest, q.date.value_or(0.0)); break;
        case Type::ENABLE_ASYNCHRONOUS_DELIVERY: c.set_asynchronous_delivery(true); break;
        case Type::DISABLE_ASYNCHRONOUS_DELIVERY: c.set_asynchronous_delivery(false); break;

        // ---- support services: the answer carries the result (libRTI reads nothing else of it) ----
        case Type::GET_OBJECT_CLASS_HANDLE: a.object_class = c.object_class_handle(q.name); break;
        case Type::GET_OBJECT_CLASS_NAME: a.name = c.object_class_name(q.object_class); break;
        case Type::GET_ATTRIBUTE_HANDLE: a.attribute = c.attribute_handle(q.name, q.object_class); break;
        case Type::GET_ATTRIBUTE_NAME: a.name = c.attribute_name(q.attribute, q.object_class); break;
        case Type::GET_INTERACTION_CLASS_HANDLE: a.interaction_class = c.interaction_class_handle(q.name); break;
        case Type::GET_INTERACTION_CLASS_NAME: a.name = c.interaction_class_name(q.interaction_class); break;
        case Type::GET_PARAMETER_HANDLE: a.parameter = c.parameter_handle(q.name, q.interaction_class); break;
        case Type::GET_PARAMETER_NAME: a.name = c.parameter_name(q.parameter, q.interaction_class); break;
        case Type::GET_OBJECT_INSTANCE_HANDLE: a.object = c.object_instance_handle(q.name); break;
        case Type::GET_OBJECT_INSTANCE_NAME: a.name = c.object_instance_name(q.object); break;
        case Type::GET_OBJECT_CLASS: a.object_class = c.object_class_of(q.object); break;
        case Type::GET_SPACE_HANDLE: a.space = c.routing_space_handle(q.name); break;
        case Type::GET_SPACE_NAME: a.name = c.routing_space_name(q.space); break;
        case Type::GET_DIMENSION_HANDLE: a.dimension = c.dimension_handle(q.name, q.space); break;
        case Type::GET_DIMENSION_NAME: a.name = c.dimension_name(q.dimension, q.space); break;
        case Type::GET_ATTRIBUTE_SPACE_HANDLE: a.space = c.attribute_routing_space(q.attribute, q.object_class); break;
        case Type::GET_INTERACTION_SPACE_HANDLE: a.space = c.interaction_routing_space(q.interaction_class); break;
        case Type::GET_TRANSPORTATION_HANDLE: a.transport = Client::transportation_handle(q.name); break;
        case Type::GET_TRANSPORTATION_NAME: a.name = Client::transportation_name(q.transport); break;
        case Type::GET_ORDERING_HANDLE: a.order = Client::ordering_handle(q.name); break;
        case Type::GET_ORDERING_NAME: a.name = Client::ordering_name(q.order); break;
        case Type::ENABLE_CLASS_RELEVANCE_ADVISORY_SWITCH:
        case Type::ENABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH:
        case Type::ENABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH:
        case Type::ENABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH:
        case Type::DISABLE_CLASS_RELEVANCE_ADVISORY_SWITCH:
        case Type::DISABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH:
        case Type::DISABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH:
        case Type::DISABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH:
            c.request(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(switch_of(q.type)), enables(q.type)});
            break;

        // ---- data distribution management: hlacore serves it, this door not yet ----
        case Type::DDM_CREATE_REGION:
        case Type::DDM_MODIFY_REGION:
        case Type::DDM_DELETE_REGION:
        case Type::DDM_REGISTER_OBJECT:
        case Type::DDM_ASSOCIATE_REGION:
        case Type::DDM_UNASSOCIATE_REGION:
        case Type::DDM_SUBSCRIBE_ATTRIBUTES:
        case Type::DDM_UNSUBSCRIBE_ATTRIBUTES:
        case Type::DDM_SUBSCRIBE_INTERACTION:
        case Type::DDM_UNSUBSCRIBE_INTERACTION:
        case Type::DDM_REQUEST_UPDATE:
            unimplemented(q, "hlacore-rtia serves no DDM yet (CERTI 3.5.1's messages carry no extents)");
        case Type::RESERVE_OBJECT_INSTANCE_NAME: c.request(wire::ReserveObjectNames{false, {q.name}}); break;
        default:
            // A callback's type, or a tick's out of place: not a request.
            raise(ErrorCode::RTIinternalError, std::string(type_name(q.type)) + " is not a request a federate sends");
    }
    return a;
}

}  // namespace hlacore::certi
