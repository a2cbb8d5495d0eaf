#include "rti/client.hpp"

#include <cerrno>
#include <cstring>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

namespace {

[[noreturn]] void raise(ErrorCode code, const std::string& message) { throw RtiError(code, message); }

std::string handle_text(std::uint32_t h) { return std::to_string(h); }

}  // namespace

Client::Client(const std::string& host, std::uint16_t port) : address_(host + ":" + std::to_string(port)) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (int rc = getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0)
        raise(ErrorCode::RTIinternalError, "cannot resolve rtig host '" + host + "': " + gai_strerror(rc));
    std::string error = "no address";
    for (addrinfo* a = found; a; a = a->ai_next) {
        int fd = ::socket(a->ai_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (fd < 0) continue;
        if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
            fd_ = fd;
            break;
        }
        error = std::strerror(errno);
        ::close(fd);
    }
    freeaddrinfo(found);
    if (fd_ < 0) raise(ErrorCode::RTIinternalError, "cannot connect to rtig at " + address_ + ": " + error);
    int one = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);

    send(wire::Hello{});
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    bool welcomed = false;
    for (;;) {
        std::vector<wire::Message> got;
        if (read_socket(deadline, got) == WaitStatus::Timeout || closed_) break;
        for (auto& m : got) {
            if (std::holds_alternative<wire::Welcome>(m)) welcomed = true;
        }
        if (welcomed) break;
    }
    if (!welcomed) {
        ::close(fd_);
        fd_ = -1;
        raise(ErrorCode::RTIinternalError, "no hlacore handshake from " + address_ +
                                               (closed_reason_.empty() ? std::string() : ": " + closed_reason_));
    }
}

Client::~Client() {
    if (fd_ >= 0) ::close(fd_);
}

// ---- plumbing ----

void Client::write_send_buffer() {
    std::size_t done = 0;
    while (done < send_buffer_.size()) {
        ssize_t n = ::send(fd_, send_buffer_.data() + done, send_buffer_.size() - done, MSG_NOSIGNAL);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            raise(ErrorCode::RTIinternalError, "connection to rtig at " + address_ + " lost: " + std::strerror(errno));
        }
    }
}

std::uint32_t Client::next_request() {
    std::lock_guard<std::mutex> lock(mu_);
    return ++last_request_;
}

wire::Reply Client::call(wire::Message request, std::uint32_t id) {
    std::visit(
        [this](const auto& m) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, std::monostate>) send(m);
        },
        request);
    for (;;) {
        auto status = pump(Clock::time_point::max(), [&] { return replies_.count(id) > 0; });
        std::unique_lock<std::mutex> lock(mu_);
        auto it = replies_.find(id);
        if (it != replies_.end()) {
            wire::Reply reply = std::move(it->second);
            replies_.erase(it);
            lock.unlock();
            if (reply.error != 0) {
                const auto code = reply.error < static_cast<std::uint16_t>(ErrorCode::Count)
                                      ? static_cast<ErrorCode>(reply.error)
                                      : ErrorCode::RTIinternalError;
                throw RtiError(code, reply.message);
            }
            return reply;
        }
        if (closed_) connection_lost();
        (void)status;  // interrupted: the reply is still owed, keep waiting
    }
}

template <class Pred>
Client::WaitStatus Client::pump(Clock::time_point deadline, Pred pred) {
    std::unique_lock<std::mutex> lock(mu_);
    bool read_once = false;  // even with a deadline already past, look at the socket once (poll_now)
    for (;;) {
        if (pred()) return WaitStatus::Ready;
        if (closed_) return WaitStatus::Ready;
        if ((read_once || reading_) && Clock::now() >= deadline) return WaitStatus::Timeout;
        if (reading_) {
            if (deadline == Clock::time_point::max()) {
                cv_.wait(lock);
            } else {
                cv_.wait_until(lock, deadline);
            }
            continue;
        }
        reading_ = true;
        read_once = true;
        lock.unlock();
        std::vector<wire::Message> got;
        WaitStatus status = WaitStatus::Ready;
        try {
            status = read_socket(deadline, got);
        } catch (...) {
            lock.lock();
            reading_ = false;
            cv_.notify_all();
            throw;
        }
        lock.lock();
        reading_ = false;
        file(got);
        cv_.notify_all();
        if (status == WaitStatus::Interrupted) return status;
    }
}

// Waits for readable data (up to the deadline), then reads everything available and decodes whole frames.
Client::WaitStatus Client::read_socket(Clock::time_point deadline, std::vector<wire::Message>& got) {
    pollfd p{fd_, POLLIN, 0};
    timespec ts{};
    const timespec* timeout = nullptr;
    if (deadline != Clock::time_point::max()) {
        auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count();
        if (left < 0) left = 0;
        ts.tv_sec = static_cast<time_t>(left / 1000000000);
        ts.tv_nsec = static_cast<long>(left % 1000000000);
        timeout = &ts;
    }
    int n = ::ppoll(&p, 1, timeout, nullptr);
    if (n < 0) return errno == EINTR ? WaitStatus::Interrupted : WaitStatus::Ready;
    if (n == 0) return WaitStatus::Timeout;
    char chunk[65536];
    std::string reason;
    for (;;) {
        ssize_t r = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT);
        if (r > 0) {
            in_.append(chunk, static_cast<std::size_t>(r));
            if (static_cast<std::size_t>(r) < sizeof chunk) break;
            continue;
        }
        if (r < 0 && errno == EINTR) continue;
        if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        reason = r == 0 ? "the gateway closed the connection" : std::strerror(errno);
        break;
    }
    std::size_t offset = 0;
    try {
        wire::Frame frame;
        while (std::size_t used = wire::next_frame(std::string_view(in_).substr(offset), frame)) {
            got.push_back(wire::decode(frame));
            offset += used;
        }
    } catch (const wire::WireError& e) {
        reason = std::string("protocol error from the gateway: ") + e.what();
    }
    in_.erase(0, offset);
    if (!reason.empty()) {
        std::lock_guard<std::mutex> lock(mu_);
        closed_ = true;
        closed_reason_ = reason;
        cv_.notify_all();
    }
    return WaitStatus::Ready;
}

// Keeps the federate's view current as messages arrive, then queues the callbacks.
void Client::file(std::vector<wire::Message>& got) {
    for (auto& m : got) {
        if (auto* r = std::get_if<wire::Reply>(&m)) {
            replies_[r->request] = std::move(*r);
            continue;
        }
        if (std::holds_alternative<wire::Welcome>(m)) continue;
        if (auto* d = std::get_if<wire::DiscoverObject>(&m)) {
            objects_[d->object] = make_local_object(d->object_class, d->name);
        } else if (auto* rm = std::get_if<wire::RemoveObject>(&m)) {
            objects_.erase(rm->object);
        } else if (auto* a = std::get_if<wire::AnnounceSyncPoint>(&m)) {
            announced_.insert(a->label);
        } else if (auto* s = std::get_if<wire::FederationSynchronized>(&m)) {
            announced_.erase(s->label);
        }
        callbacks_.push(std::move(m));
    }
}

std::string Client::query_status() {
    const auto id = next_request();
    return call(wire::QueryStatus{id}, id).text;
}

void Client::poll_now() { pump(Clock::now(), [] { return false; }); }

Client::WaitStatus Client::wait_for_callback(Clock::time_point deadline) {
    return pump(deadline, [this] { return !callbacks_.empty(); });
}

std::optional<wire::Message> Client::pop_callback() {
    std::lock_guard<std::mutex> lock(mu_);
    if (callbacks_.empty()) {
        if (closed_) connection_lost();
        return std::nullopt;
    }
    wire::Message m = callbacks_.pop();
    apply_time_callback(m);
    apply_ownership_callback(m);
    apply_save_callback(m);
    return m;
}

bool Client::has_callbacks() const {
    std::lock_guard<std::mutex> lock(mu_);
    return !callbacks_.empty();
}

void Client::connection_lost() const {
    raise(ErrorCode::RTIinternalError, "connection to rtig at " + address_ + " lost: " + closed_reason_);
}

// ---- checks ----

void Client::require_joined() const {
    if (!fom_) raise(ErrorCode::FederateNotExecutionMember, "the federate is not joined to a federation execution");
    if (closed_) connection_lost();
}

const fom::ObjectClass& Client::defined_object_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->object_class(cls);
    if (!c) raise(ErrorCode::ObjectClassNotDefined, "object class handle " + handle_text(cls) + " is not defined");
    return *c;
}

const fom::InteractionClass& Client::defined_interaction_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->interaction_class(cls);
    if (!c)
        raise(ErrorCode::InteractionClassNotDefined, "interaction class handle " + handle_text(cls) + " is not defined");
    return *c;
}

const Client::LocalObject& Client::known_object(std::uint32_t object) const {
    require_joined();
    auto it = objects_.find(object);
    if (it == objects_.end()) raise(ErrorCode::ObjectNotKnown, "object " + handle_text(object) + " is not known");
    return it->second;
}

namespace {
void check_attributes(const fom::ObjectClass& cls, const std::vector<fom::Handle>& attributes) {
    for (auto a : attributes) {
        if (!cls.attribute(a))
            raise(ErrorCode::AttributeNotDefined,
                  "attribute handle " + handle_text(a) + " is not defined for class '" + cls.qualified_name + "'");
    }
}
}  // namespace

// ---- federation management ----

void Client::create_federation(const std::string& name, const std::string& fed_name, const std::string& fed_text) {
    const auto id = next_request();
    call(wire::CreateFederation{id, name, fed_name, fed_text}, id);
}

void Client::destroy_federation(const std::string& name) {
    const auto id = next_request();
    call(wire::DestroyFederation{id, name}, id);
}

std::uint32_t Client::join(const std::string& federate, const std::string& federation) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (fom_) raise(ErrorCode::FederateAlreadyExecutionMember, "this ambassador is already joined");
    }
    const auto id = next_request();
    wire::Reply reply = call(wire::JoinFederation{id, federate, federation}, id);
    auto parsed = std::make_unique<fom::Fom>(fom::parse_fed(reply.text, reply.text2));
    std::lock_guard<std::mutex> lock(mu_);
    fom_ = std::move(parsed);
    federate_ = reply.handle;
    return reply.handle;
}

void Client::resign(std::uint8_t action) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        check_not_saving_or_restoring("resignFederationExecution");
        if (action < 1 || action > 4)
            raise(ErrorCode::InvalidResignAction, "resign action " + std::to_string(action) + " is not one of 1-4");
    }
    const auto id = next_request();
    call(wire::ResignFederation{id, action}, id);
    std::lock_guard<std::mutex> lock(mu_);
    fom_.reset();
    federate_ = 0;
    published_.clear();
    subscribed_.clear();
    published_interactions_.clear();
    subscribed_interactions_.clear();
    objects_.clear();
    announced_.clear();
    time_ = TimeState{};
    save_phase_ = SavePhase::None;
    restore_phase_ = RestorePhase::None;
    ddm_ = DdmState{};
}

void Client::register_sync_point(const std::string& label, const std::string& tag,
                                 const std::optional<std::vector<std::uint32_t>>& federates) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    send(wire::RegisterSyncPoint{label, tag, !federates.has_value(), federates.value_or(wire::Handles{})});
}

void Client::sync_point_achieved(const std::string& label) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        if (!announced_.count(label))
            raise(ErrorCode::SynchronizationPointLabelWasNotAnnounced,
                  "synchronization point '" + label + "' was not announced to this federate");
    }
    send(wire::SyncPointAchieved{label});
}

// ---- declaration management ----

void Client::publish_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes) {
    std::vector<wire::UnconditionalDivestiture> divested;
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
        if (attributes.empty()) {
            published_.erase(cls);
        } else {
            published_[cls] = std::set<fom::Handle>(attributes.begin(), attributes.end());
        }
        divested = divest_unpublished(cls);
    }
    for (const auto& m : divested) send(m);
    send(wire::PublishObjectClass{cls, attributes});
}

void Client::unpublish_object_class(fom::Handle cls) {
    std::vector<wire::UnconditionalDivestiture> divested;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        if (!published_.count(cls))
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        // HLA 1.3 §5.3: not while this federate waits to acquire attributes of an instance of the class.
        for (const auto& [h, obj] : objects_) {
            if (obj.object_class == cls && (!obj.acquiring.empty() || !obj.acquiring_if_available.empty()))
                raise(ErrorCode::OwnershipAcquisitionPending,
                      "an ownership acquisition is pending for object '" + obj.name + "' of class '" +
                          c.qualified_name + "'");
        }
        published_.erase(cls);
        divested = divest_unpublished(cls);
    }
    for (const auto& m : divested) send(m);
    send(wire::UnpublishObjectClass{cls});
}

void Client::subscribe_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes, bool active) {
    (void)active;  // passive subscriptions only change advisories, which follow any subscription here
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
        if (attributes.empty()) {
            subscribed_.erase(cls);
        } else {
            subscribed_[cls] = std::set<fom::Handle>(attributes.begin(), attributes.end());
        }
    }
    send(wire::SubscribeObjectClass{cls, attributes, active});
}

void Client::unsubscribe_object_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        if (!subscribed_.erase(cls))
            raise(ErrorCode::ObjectClassNotSubscribed, "object class '" + c.qualified_name + "' is not subscribed");
    }
    send(wire::UnsubscribeObjectClass{cls});
}

void Client::publish_interaction_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        defined_interaction_class(cls);
        published_interactions_.insert(cls);
    }
    send(wire::PublishInteractionClass{cls});
}

void Client::unpublish_interaction_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!published_interactions_.erase(cls))
            raise(ErrorCode::InteractionClassNotPublished,
                  "interaction class '" + c.qualified_name + "' is not published");
    }
    send(wire::UnpublishInteractionClass{cls});
}

void Client::subscribe_interaction_class(fom::Handle cls, bool active) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        defined_interaction_class(cls);
        subscribed_interactions_.insert(cls);
    }
    send(wire::SubscribeInteractionClass{cls, active});
}

void Client::unsubscribe_interaction_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!subscribed_interactions_.erase(cls))
            raise(ErrorCode::InteractionClassNotSubscribed,
                  "interaction class '" + c.qualified_name + "' is not subscribed");
    }
    send(wire::UnsubscribeInteractionClass{cls});
}

void Client::set_advisory_switch(wire::AdvisorySwitch which, bool on) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    send(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(which), on});
}

// ---- object management ----

std::uint32_t Client::register_object(fom::Handle cls, const std::string& name) {
    std::set<fom::Handle> owned;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        check_not_saving_or_restoring("registerObjectInstance");
        auto it = published_.find(cls);
        if (it == published_.end())
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        owned = it->second;
    }
    const auto id = next_request();
    wire::Reply reply = call(wire::RegisterObject{id, cls, name}, id);
    std::lock_guard<std::mutex> lock(mu_);
    LocalObject obj = make_local_object(cls, reply.text);
    obj.owned = std::move(owned);
    // The registrant holds the privilege to delete (HLA 1.3 §6.2), the privilegeToDelete attribute if any.
    if (obj.privilege_attribute) obj.owned.insert(obj.privilege_attribute);
    obj.privilege_to_delete = true;
    objects_[reply.handle] = std::move(obj);
    return reply.handle;
}

std::uint64_t Client::update_attributes(std::uint32_t object, wire::HandleValues values, const std::string& tag,
                                        wire::OptionalTime time) {
    std::uint64_t serial;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        check_not_saving_or_restoring("updateAttributeValues");
        const auto& cls = *fom_->object_class(obj.object_class);
        for (const auto& [attr, value] : values) {
            if (!cls.attribute(attr))
                raise(ErrorCode::AttributeNotDefined, "attribute handle " + handle_text(attr) +
                                                          " is not defined for class '" + cls.qualified_name + "'");
            if (!obj.owned.count(attr))
                raise(ErrorCode::AttributeNotOwned, "attribute '" + cls.attribute(attr)->name + "' of object '" +
                                                        obj.name + "' is not owned by this federate");
        }
        check_send_time(time);
        serial = ++serial_;
        note_sent(serial, time);
    }
    send(wire::UpdateAttributes{object, std::move(values), tag, time, serial});
    return serial;
}

std::uint64_t Client::send_interaction(fom::Handle cls, wire::HandleValues values, const std::string& tag,
                                       wire::OptionalTime time) {
    std::uint64_t serial;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        check_not_saving_or_restoring("sendInteraction");
        if (!published_interactions_.count(cls))
            raise(ErrorCode::InteractionClassNotPublished,
                  "interaction class '" + c.qualified_name + "' is not published");
        for (const auto& [param, value] : values) {
            if (!c.parameter(param))
                raise(ErrorCode::InteractionParameterNotDefined, "parameter handle " + handle_text(param) +
                                                                     " is not defined for interaction '" +
                                                                     c.qualified_name + "'");
        }
        check_send_time(time);
        serial = ++serial_;
        note_sent(serial, time);
    }
    send(wire::SendInteraction{cls, std::move(values), tag, time, serial});
    return serial;
}

std::uint64_t Client::delete_object(std::uint32_t object, const std::string& tag, wire::OptionalTime time) {
    std::uint64_t serial;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        check_not_saving_or_restoring("deleteObjectInstance");
        if (!obj.privilege_to_delete)
            raise(ErrorCode::DeletePrivilegeNotHeld, "this federate may not delete object '" + obj.name + "'");
        check_send_time(time);
        objects_.erase(object);
        serial = ++serial_;
        note_sent(serial, time);
    }
    send(wire::DeleteObject{object, tag, time, serial});
    return serial;
}

void Client::local_delete_object(std::uint32_t object) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        if (!obj.owned.empty())
            raise(ErrorCode::FederateOwnsAttributes,
                  "this federate owns attributes of object '" + obj.name + "' and cannot delete it locally");
        objects_.erase(object);
    }
    send(wire::LocalDeleteObject{object});
}

void Client::request_object_update(std::uint32_t object, const std::vector<fom::Handle>& attributes) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        check_attributes(*fom_->object_class(obj.object_class), attributes);
    }
    send(wire::RequestObjectUpdate{object, attributes});
}

void Client::request_class_update(fom::Handle cls, const std::vector<fom::Handle>& attributes) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
    }
    send(wire::RequestClassUpdate{cls, attributes});
}

// ---- transport and order changes (HLA 1.3 §6.19-6.22) ----

namespace {

std::uint8_t transport_value(std::uint32_t transport) {
    if (transport != static_cast<std::uint32_t>(fom::Transport::Reliable) &&
        transport != static_cast<std::uint32_t>(fom::Transport::BestEffort))
        raise(ErrorCode::InvalidTransportationHandle,
              "transportation handle " + handle_text(transport) + " is not a transportation type");
    return static_cast<std::uint8_t>(transport);
}

std::uint8_t order_value(std::uint32_t order) {
    if (order != static_cast<std::uint32_t>(fom::Order::Receive) &&
        order != static_cast<std::uint32_t>(fom::Order::Timestamp))
        raise(ErrorCode::InvalidOrderingHandle, "ordering handle " + handle_text(order) + " is not an ordering type");
    return static_cast<std::uint8_t>(order);
}

}  // namespace

void Client::change_attribute_transportation(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                             std::uint32_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_attribute_delivery(object, attributes, 0, transport_value(transport));
}

void Client::change_attribute_order(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                    std::uint32_t order) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_attribute_delivery(object, attributes, order_value(order), 0);
}

void Client::change_interaction_transportation(fom::Handle cls, std::uint32_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_interaction_delivery(cls, 0, transport_value(transport));
}

void Client::change_interaction_order(fom::Handle cls, std::uint32_t order) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_interaction_delivery(cls, order_value(order), 0);
}

// §6.19, §6.21: only the owner of every named attribute may change them.
void Client::change_attribute_delivery(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                       std::uint8_t order, std::uint8_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        const auto& cls = *fom_->object_class(obj.object_class);
        check_attributes(cls, attributes);
        for (auto a : attributes) {
            if (!obj.owned.count(a))
                raise(ErrorCode::AttributeNotOwned, "attribute '" + cls.attribute(a)->name + "' of object '" +
                                                        obj.name + "' is not owned by this federate");
        }
    }
    send(wire::ChangeAttributeDelivery{object, attributes, order, transport});
}

// §6.20, §6.22: only a publisher of the class may change it.
void Client::change_interaction_delivery(fom::Handle cls, std::uint8_t order, std::uint8_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!published_interactions_.count(cls))
            raise(ErrorCode::InteractionClassNotPublished,
                  "interaction class '" + c.qualified_name + "' is not published");
    }
    send(wire::ChangeInteractionDelivery{cls, order, transport});
}

// ---- support services ----

fom::Handle Client::object_class_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* c = fom_->find_object_class(name);
    if (!c) raise(ErrorCode::NameNotFound, "no object class named '" + name + "'");
    return c->handle;
}

std::string Client::object_class_name(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_object_class(cls).qualified_name;
}

fom::Handle Client::attribute_handle(const std::string& name, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(name);
    if (!a) raise(ErrorCode::NameNotFound, "class '" + c.qualified_name + "' has no attribute named '" + name + "'");
    return a->handle;
}

std::string Client::attribute_name(fom::Handle attribute, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(attribute);
    if (!a)
        raise(ErrorCode::AttributeNotDefined,
              "attribute handle " + handle_text(attribute) + " is not defined for class '" + c.qualified_name + "'");
    return a->name;
}

fom::Handle Client::interaction_class_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* c = fom_->find_interaction_class(name);
    if (!c) raise(ErrorCode::NameNotFound, "no interaction class named '" + name + "'");
    return c->handle;
}

std::string Client::interaction_class_name(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_interaction_class(cls).qualified_name;
}

fom::Handle Client::parameter_handle(const std::string& name, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* p = c.parameter(name);
    if (!p) raise(ErrorCode::NameNotFound, "interaction '" + c.qualified_name + "' has no parameter named '" + name + "'");
    return p->handle;
}

std::string Client::parameter_name(fom::Handle parameter, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* p = c.parameter(parameter);
    if (!p)
        raise(ErrorCode::InteractionParameterNotDefined, "parameter handle " + handle_text(parameter) +
                                                             " is not defined for interaction '" + c.qualified_name + "'");
    return p->name;
}

std::uint32_t Client::object_instance_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    for (const auto& [h, obj] : objects_) {
        if (obj.name == name) return h;
    }
    raise(ErrorCode::ObjectNotKnown, "no object named '" + name + "' is known to this federate");
}

std::string Client::object_instance_name(std::uint32_t object) const {
    std::lock_guard<std::mutex> lock(mu_);
    return known_object(object).name;
}

fom::Handle Client::object_class_of(std::uint32_t object) const {
    std::lock_guard<std::mutex> lock(mu_);
    return known_object(object).object_class;
}

fom::Handle Client::routing_space_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->find_space(name);
    if (!s) raise(ErrorCode::NameNotFound, "no routing space named '" + name + "'");
    return s->handle;
}

std::string Client::routing_space_name(fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + handle_text(space) + " is not defined");
    return s->name;
}

fom::Handle Client::dimension_handle(const std::string& name, fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + handle_text(space) + " is not defined");
    for (const auto& d : s->dimensions)
        if (d.name == name) return d.handle;
    raise(ErrorCode::NameNotFound, "routing space '" + s->name + "' has no dimension named '" + name + "'");
}

std::string Client::dimension_name(fom::Handle dimension, fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + handle_text(space) + " is not defined");
    for (const auto& d : s->dimensions)
        if (d.handle == dimension) return d.name;
    raise(ErrorCode::DimensionNotDefined, "dimension handle " + handle_text(dimension) + " is not defined in '" +
                                              s->name + "'");
}

fom::Handle Client::attribute_routing_space(fom::Handle attribute, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(attribute);
    if (!a) raise(ErrorCode::AttributeNotDefined, "attribute handle " + handle_text(attribute) + " is not defined");
    const auto* s = a->space.empty() ? nullptr : fom_->find_space(a->space);
    return s ? s->handle : 0;
}

fom::Handle Client::interaction_routing_space(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* s = c.space.empty() ? nullptr : fom_->find_space(c.space);
    return s ? s->handle : 0;
}

std::uint32_t Client::federate_handle() const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return federate_;
}

}  // namespace hlacore
