// The federate side of ownership management (HLA 1.3 §7): the services check HLA 1.3's exceptions
// against the federate's view of each object; the gateway decides the transfers. What this federate owns
// changes when a notification callback is popped (as time state does in client/time.cpp), or at once
// when a call gives attributes up (unconditional divestiture, release response).

#include "rti/client/client.hpp"

namespace hlacore {

Client::LocalObject Client::make_local_object(fom::Handle cls, const std::string& name) const {
    LocalObject obj;
    obj.object_class = cls;
    obj.name = name;
    if (const auto* c = fom_ ? fom_->object_class(cls) : nullptr) {
        if (const auto* privilege = c->privilege_to_delete()) obj.privilege_attribute = privilege->handle;
    }
    return obj;
}

Client::LocalObject& Client::ownership_object(std::uint32_t object, const std::vector<fom::Handle>& attributes) {
    LocalObject& obj = known_object(object);
    const auto& cls = *fom_->object_class(obj.object_class);
    for (auto a : attributes) {
        if (!cls.attribute(a))
            raise(ErrorCode::AttributeNotDefined, "attribute handle " + std::to_string(a) +
                                                      " is not defined for class '" + cls.qualified_name + "'");
    }
    return obj;
}

namespace {

// "attribute 'location' of object 'r1'"
template <class Obj>
std::string describe(const fom::Fom& fom, const Obj& obj, fom::Handle attr) {
    const auto* a = fom.object_class(obj.object_class)->attribute(attr);
    return "attribute '" + (a ? a->name : std::to_string(attr)) + "' of object '" + obj.name + "'";
}

// Each attribute must be owned by this federate (AttributeNotOwned), then pass `also`, the service's own check.
template <class Obj, class Also>
void check_owned(const fom::Fom& fom, const Obj& obj, const std::vector<fom::Handle>& attributes, Also also) {
    for (auto a : attributes) {
        if (!obj.owned.count(a))
            raise(ErrorCode::AttributeNotOwned, describe(fom, obj, a) + " is not owned by this federate");
        also(a);
    }
}

}  // namespace

// §7.2: the attributes are no longer this federate's as soon as the call returns.
void Client::unconditional_divestiture(std::uint32_t object, const std::vector<fom::Handle>& attributes) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        LocalObject& obj = ownership_object(object, attributes);
        check_owned(*fom_, obj, attributes, [](fom::Handle) {});
        for (auto a : attributes) obj.lose(a);
    }
    send(wire::UnconditionalDivestiture{object, attributes});
}

// §7.3: the federate keeps the attributes until attributeOwnershipDivestitureNotification.
void Client::negotiated_divestiture(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                    const std::string& tag) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        LocalObject& obj = ownership_object(object, attributes);
        check_owned(*fom_, obj, attributes, [&](fom::Handle a) {
            if (obj.divesting.count(a))
                raise(ErrorCode::AttributeAlreadyBeingDivested, describe(*fom_, obj, a) + " is already being divested");
        });
        obj.divesting.insert(attributes.begin(), attributes.end());
    }
    send(wire::NegotiatedDivestiture{object, attributes, tag});
}

bool Client::publishes(const LocalObject& obj, fom::Handle attribute) const {
    auto pub = declarations_.published.find(obj.object_class);
    return pub != declarations_.published.end() && (pub->second.count(attribute) || attribute == obj.privilege_attribute);
}

std::vector<wire::UnconditionalDivestiture> Client::divest_unpublished(fom::Handle cls) {
    std::vector<wire::UnconditionalDivestiture> out;
    for (auto& [h, obj] : objects_) {
        if (obj.object_class != cls) continue;
        wire::UnconditionalDivestiture m{h, {}};
        for (auto a : obj.owned)
            if (!publishes(obj, a)) m.attributes.push_back(a);
        if (m.attributes.empty()) continue;
        for (auto a : m.attributes) obj.lose(a);
        out.push_back(std::move(m));
    }
    return out;
}

namespace {

// The checks shared by the two acquisition services (§7.7, §7.8): the object's class and the attributes
// must be published, and not already owned.
template <class Obj, class Publishes>
void check_acquirable(const fom::Fom& fom, bool class_published, Publishes publishes, const Obj& obj,
                      const std::vector<fom::Handle>& attributes) {
    if (!class_published)
        raise(ErrorCode::ObjectClassNotPublished,
              "object class '" + fom.object_class(obj.object_class)->qualified_name + "' is not published");
    for (auto a : attributes) {
        if (!publishes(a))
            raise(ErrorCode::AttributeNotPublished, describe(fom, obj, a) + " is not published by this federate");
        if (obj.owned.count(a))
            raise(ErrorCode::FederateOwnsAttributes, describe(fom, obj, a) + " is already owned by this federate");
    }
}

}  // namespace

// §7.7: acquired at once if unowned or being divested, else once its owner releases it.
void Client::ownership_acquisition(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                   const std::string& tag) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        LocalObject& obj = ownership_object(object, attributes);
        check_acquirable(*fom_, declarations_.published.count(obj.object_class) > 0,
                         [&](fom::Handle a) { return publishes(obj, a); }, obj, attributes);
        obj.acquiring.insert(attributes.begin(), attributes.end());
    }
    send(wire::OwnershipAcquisition{object, attributes, tag});
}

// §7.8: answered by attributeOwnershipAcquisitionNotification or attributeOwnershipUnavailable.
void Client::ownership_acquisition_if_available(std::uint32_t object, const std::vector<fom::Handle>& attributes) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        LocalObject& obj = ownership_object(object, attributes);
        check_acquirable(*fom_, declarations_.published.count(obj.object_class) > 0,
                         [&](fom::Handle a) { return publishes(obj, a); }, obj, attributes);
        for (auto a : attributes)
            if (obj.acquiring.count(a) || obj.acquiring_if_available.count(a))
                raise(ErrorCode::AttributeAlreadyBeingAcquired, describe(*fom_, obj, a) + " is already being acquired");
        obj.acquiring_if_available.insert(attributes.begin(), attributes.end());
    }
    send(wire::OwnershipAcquisitionIfAvailable{object, attributes});
}

// §7.11: a round trip, since only the gateway knows who still waits for each attribute.
std::vector<fom::Handle> Client::release_response(std::uint32_t object, const std::vector<fom::Handle>& attributes) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        LocalObject& obj = ownership_object(object, attributes);
        check_owned(*fom_, obj, attributes, [&](fom::Handle a) {
            if (!obj.release_requested.count(a))
                raise(ErrorCode::FederateWasNotAskedToReleaseAttribute,
                      "this federate was not asked to release " + describe(*fom_, obj, a));
        });
    }
    const auto id = next_request();
    std::vector<fom::Handle> released =
        call<wire::AttributesReleased>(wire::ReleaseResponse{id, object, attributes}, id).attributes;
    std::lock_guard<std::mutex> lock(mu_);
    auto it = objects_.find(object);
    if (it != objects_.end()) {
        LocalObject& obj = it->second;
        for (auto a : attributes) obj.release_requested.erase(a);
        for (auto a : released) obj.lose(a);
    }
    return released;
}

// §7.12.
void Client::check(const wire::CancelNegotiatedDivestiture& m) {
    LocalObject& obj = ownership_object(m.object, m.attributes);
    check_owned(*fom_, obj, m.attributes, [&](fom::Handle a) {
        if (!obj.divesting.count(a))
            raise(ErrorCode::AttributeDivestitureWasNotRequested,
                  "no negotiated divestiture of " + describe(*fom_, obj, a) + " is in progress");
    });
    for (auto a : m.attributes) obj.divesting.erase(a);
}

// §7.13: confirmAttributeOwnershipAcquisitionCancellation follows for what was still awaited; an
// attribute acquired meanwhile arrives with attributeOwnershipAcquisitionNotification instead.
void Client::check(const wire::CancelOwnershipAcquisition& m) {
    LocalObject& obj = ownership_object(m.object, m.attributes);
    for (auto a : m.attributes) {
        if (obj.owned.count(a))
            raise(ErrorCode::AttributeAlreadyOwned, describe(*fom_, obj, a) + " is already owned by this federate");
        if (!obj.acquiring.count(a))
            raise(ErrorCode::AttributeAcquisitionWasNotRequested,
                  "no acquisition of " + describe(*fom_, obj, a) + " is pending");
    }
}

// §7.15: answered by informAttributeOwnership, attributeIsNotOwned or attributeOwnedByRTI.
void Client::check(const wire::QueryOwnership& m) { ownership_object(m.object, {m.attribute}); }

// §7.17: answered locally, from the notifications delivered so far.
bool Client::is_owned(std::uint32_t object, fom::Handle attribute) const {
    std::lock_guard<std::mutex> lock(mu_);
    const LocalObject& obj = known_object(object);
    const auto& cls = *fom_->object_class(obj.object_class);
    if (!cls.attribute(attribute))
        raise(ErrorCode::AttributeNotDefined, "attribute handle " + std::to_string(attribute) +
                                                  " is not defined for class '" + cls.qualified_name + "'");
    return obj.owned.count(attribute) > 0;
}

// When a notification is popped the federate's view follows what it is told, for each attribute it names,
// unless the object is gone meanwhile.
namespace {
template <class Objects, class Callback, class Change>
void for_each_attribute(Objects& objects, const Callback& callback, Change change) {
    auto it = objects.find(callback.object);
    if (it == objects.end()) return;
    for (auto a : callback.attributes) change(it->second, a);
}
}  // namespace

void Client::delivered(const wire::AcquisitionNotification& m) {
    for_each_attribute(objects_, m, [](LocalObject& obj, fom::Handle a) { obj.gain(a); });
}

void Client::delivered(const wire::DivestitureNotification& m) {
    for_each_attribute(objects_, m, [](LocalObject& obj, fom::Handle a) { obj.lose(a); });
}

void Client::delivered(const wire::OwnershipUnavailable& m) {
    for_each_attribute(objects_, m, [](LocalObject& obj, fom::Handle a) { obj.acquiring_if_available.erase(a); });
}

void Client::delivered(const wire::RequestOwnershipRelease& m) {
    for_each_attribute(objects_, m, [](LocalObject& obj, fom::Handle a) {
        if (obj.owned.count(a)) obj.release_requested.insert(a);
    });
}

void Client::delivered(const wire::ConfirmAcquisitionCancellation& m) {
    for_each_attribute(objects_, m, [](LocalObject& obj, fom::Handle a) { obj.acquiring.erase(a); });
}

}  // namespace hlacore
