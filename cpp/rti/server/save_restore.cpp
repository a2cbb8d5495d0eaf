// Federation save and restore (HLA 1.3 §4.11-4.22) as the gateway runs them; the contract, the file
// format and the choices made where HLA 1.3 leaves room are in docs/save-restore.md.
//
// A save: initiateFederateSave goes to every federate (for a timed save, to a time-managed federate once
// it is granted the save time or beyond); from then on what the federation sends it is held (delivered
// after federationSaved, and part of the save), and once every federate was told, grants and timestamped
// deliveries wait too. When every federate has answered
// federateSaveComplete the gateway encodes its own part (declarations, objects and owners, time state,
// queued and held messages), keeps it by label and, with a save directory, writes it to a file.
//
// A restore replaces the federation's state by a save whose federates have the names of those joined
// now; they get back the handles they had in the save, and each is sent its mirrored state with
// initiateFederateRestore. Until a federate answers, what it sends is ignored: it belongs to the world
// being replaced.
#include "rti/server/save_restore.hpp"
#include "rti/server/federation.hpp"
#include "rti/wire/json.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

namespace hlacore {

using wire::WireError;

// The save file's format and records: a named namespace, not an anonymous one, since Federation::Snapshot
// (declared in federation.hpp) holds them.
namespace save_file {

constexpr char kFileMagic[8] = {'H', 'L', 'A', 'C', 'S', 'A', 'V', 'E'};
// Version 2 added data distribution management; version 1 files (no regions) are refused, since
// restoring one would silently drop the regions federates hold handles to. Version 3: an attribute's
// update_regions may repeat, one record per region (IEEE 1516-2010's several); a version 2 file, one record
// an attribute, reads the same, and a version 2 gateway refuses a version 3 file rather than keep one region.
// Version 4 appends HLA 4's directed interaction declarations, none in an older file.
constexpr std::uint32_t kFormatVersion = 4;
constexpr std::uint32_t kOldestReadableVersion = 2;

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
struct ObjectAttributes {  // an object and attributes of it
    std::uint32_t object = 0;
    wire::Handles attributes;
    HLACORE_FIELDS(object, attributes)
};

struct FederateRecord {
    std::uint32_t handle = 0;
    std::string name;
    std::vector<wire::ClassAttributes> published;
    std::vector<wire::ClassAttributes> subscribed;
    wire::Handles published_interactions;
    wire::Handles subscribed_interactions;
    wire::Handles known;
    wire::Handles registration_started;
    wire::Handles interactions_turned_on;
    bool class_relevance = true;
    bool interaction_relevance = true;
    bool attribute_relevance = false;
    bool attribute_scope = false;
    Pairs interaction_order;
    Pairs interaction_transport;
    // Time state, queued timestamped messages and receive-order ones held by time management.
    TimeManager::SavedState time_management;
    std::vector<std::string> held_after_save;  // sent during the save, delivered after federationSaved
    // Data distribution management (HLA 1.3 §9), as initiateFederateRestore carries it to the client.
    std::vector<wire::RegionRecord> regions;
    std::vector<wire::RegionSubscription> region_subscriptions;
    std::vector<wire::InteractionRegion> region_interaction_subscriptions;
    std::vector<wire::UpdateRegion> update_regions;
    std::vector<ObjectAttributes> in_scope;  // attributes last reported in scope (attribute scope advisory)
    std::vector<ObjectAttributes> relevant;  // owned attributes last reported relevant (turnUpdatesOn)
    std::uint32_t last_region = 0;
    HLACORE_FIELDS(handle, name, published, subscribed, published_interactions, subscribed_interactions, known,
                   registration_started, interactions_turned_on, class_relevance, interaction_relevance,
                   attribute_relevance, attribute_scope, interaction_order, interaction_transport, time_management,
                   held_after_save, regions, region_subscriptions, region_interaction_subscriptions,
                   update_regions, in_scope, relevant, last_region)
};

struct DirectedRecord {  // a federate's HLA 4 directed interaction declarations (version 4)
    std::uint32_t federate = 0;
    std::vector<wire::ClassAttributes> published;
    std::vector<wire::ClassAttributes> subscribed;
    std::vector<wire::ClassAttributes> universally;
    HLACORE_FIELDS(federate, published, subscribed, universally)
};

struct ObjectRecord {
    std::uint32_t handle = 0;
    std::uint32_t object_class = 0;
    std::string name;
    std::uint32_t privilege_attribute = 0;
    std::uint32_t privilege_holder = 0;
    Pairs owners;  // attribute -> owner
    Pairs order;
    Pairs transport;
    HLACORE_FIELDS(handle, object_class, name, privilege_attribute, privilege_holder, owners, order, transport)
};

// A map handle -> set of attributes as records {handle, attributes}.
template <class Record, class Map>
std::vector<Record> records_of(const Map& m) {
    std::vector<Record> out;
    for (const auto& [handle, attrs] : m) out.push_back(Record{handle, wire::Handles(attrs.begin(), attrs.end())});
    return out;
}

template <class Map>
Pairs pairs(const Map& m) {
    Pairs out;
    for (const auto& [k, v] : m) out.emplace_back(k, static_cast<std::uint32_t>(v));
    return out;
}

template <class Set>
wire::Handles handles(const Set& s) {
    return wire::Handles(s.begin(), s.end());
}

// A federate's regions, region subscriptions and update associations into a FederateRecord or an
// initiateFederateRestore (same field names); a region's extents are flattened into lower, upper pairs.
template <class Ddm, class Target>
void put_ddm(const Ddm& ddm, Target& out) {
    for (const auto& [handle, region] : ddm.regions) {
        wire::Handles bounds;
        for (const auto& extent : region.extents) {
            for (const auto& [lower, upper] : extent) {
                bounds.push_back(lower);
                bounds.push_back(upper);
            }
        }
        out.regions.push_back({handle, region.space, std::move(bounds)});
    }
    for (const auto& [cls, by_region] : ddm.object_subscriptions)
        for (const auto& [region, attrs] : by_region) out.region_subscriptions.push_back({cls, region, handles(attrs)});
    for (const auto& [ic, regions] : ddm.interaction_subscriptions)
        for (auto region : regions) out.region_interaction_subscriptions.push_back({ic, region});
    for (const auto& [object, associations] : ddm.update_regions)
        for (const auto& [attr, regions] : associations)
            for (auto region : regions) out.update_regions.push_back({object, attr, region});
    out.last_region = ddm.last_region;
}


// File names keep letters, digits, '_' and '.'; anything else becomes %XX, so that no label reaches
// outside the save directory and "--" can separate the federation from the label.
std::string file_component(const std::string& s) {
    std::string out;
    for (unsigned char c : s) {
        if (std::isalnum(c) || c == '_' || (c == '.' && !out.empty())) {
            out += static_cast<char>(c);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", c);
            out += hex;
        }
    }
    return out.empty() ? "%" : out;
}

std::string join_names(const std::set<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

// A queued or held frame from a save must be one whole message the gateway could have sent: a corrupt
// one would make the receiving client drop its connection.
void check_frame(const std::string& frame) {
    wire::Frame f;
    if (wire::next_frame(frame, f) != frame.size()) throw WireError("a saved message is not one whole frame");
    wire::decode(f);
}

template <class Pairs_>
void check_delivery_values(const Pairs_& values, const std::string& whose) {
    for (const auto& [handle, v] : values)
        if (v < 1 || v > 2) throw WireError("bad order or transport value in " + whose);
}


}  // namespace save_file

using namespace save_file;

struct Federation::Snapshot {
    std::string label;
    std::string federation;
    std::string fed_name;
    std::string fed_text;
    std::uint32_t next_federate = 1;
    std::uint32_t next_object = 1;
    wire::OptionalTime time;
    std::vector<FederateRecord> federates;
    std::vector<ObjectRecord> objects;
    std::vector<DirectedRecord> directed;
};

// ---- the state (save_restore.hpp) ----

void SaveRestore::check_idle(const char* service) const {
    if (save.active)
        throw RtiError(ErrorCode::SaveInProgress,
                       std::string(service) + " refused: the federation save '" + save.label + "' is in progress");
    if (restore.active)
        throw RtiError(ErrorCode::RestoreInProgress,
                       std::string(service) + " refused: the federation restore '" + restore.label + "' is in progress");
}

void SaveRestore::check_saving() const {
    if (!save.active) throw RtiError(ErrorCode::SaveNotInProgress, "no federation save is in progress");
}

void SaveRestore::check_restoring() const {
    if (!restore.active) throw RtiError(ErrorCode::RestoreNotInProgress, "no federation restore is in progress");
}

void SaveRestore::check_not_restoring() const {
    if (restore.active)
        throw RtiError(ErrorCode::RestoreInProgress, "the federation restore '" + restore.label + "' is in progress");
}

std::string SaveRestore::file(const std::string& federation, const std::string& label) const {
    return dir + "/" + file_component(federation) + "--" + file_component(label) + ".hlasave";
}

bool SaveRestore::keep(const std::string& federation, const std::string& label, std::string bytes) {
    error.clear();
    if (!dir.empty()) {
        const std::string path = file(federation, label);
        const std::string partial = path + ".partial";
        ::mkdir(dir.c_str(), 0777);
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out || std::rename(partial.c_str(), path.c_str()) != 0) {
            error = "cannot write " + path + ": " + std::strerror(errno);
            std::remove(partial.c_str());
            return false;
        }
    }
    saves[label] = std::move(bytes);
    return true;
}

// ---- requests ----

void Federation::check_membership_change(const char* service) const { save_restore_.check_idle(service); }

// HLA 1.3 §4.11.
void Federation::request_save(FederateHandle from, const std::string& label, const wire::OptionalTime& time) {
    federate(from);
    check_membership_change("requestFederationSave");
    if (time) {
        if (!std::isfinite(*time))
            throw RtiError(ErrorCode::InvalidFederationTime, "the save time " + time_text(*time) + " is not finite");
        // A time-managed federate already past the save time could not save at it.
        for (const auto& [h, f] : federates_) {
            if ((time_.regulating(h) || time_.constrained(h)) && time_.federate_time(h) > *time)
                throw RtiError(ErrorCode::FederationTimeAlreadyPassed,
                               "federate '" + f.name + "' is at time " + time_text(time_.federate_time(h)) +
                                   ", past the save time " + time_text(*time));
        }
    }
    save_restore_.save = SaveRestore::SaveRun{};
    save_restore_.save.active = true;
    save_restore_.save.label = label;
    save_restore_.save.time = time;
    outbox_.holding = &save_restore_.save.held;
    tell_savers();
    release_time();  // for a timed save: pending requests beyond its time now stop there
}

// initiateFederateSave (§4.12) to whoever may save now: everyone for an untimed save; for a timed one,
// federates that are neither regulating nor constrained at once, the others once granted the save time
// or beyond and not advancing (a regulator told at once could not advance, and could hold the
// constrained federates below the save time for ever).
void Federation::tell_savers() {
    for (const auto& [h, f] : federates_) {
        if (save_restore_.save.told.count(h)) continue;
        if (save_restore_.save.time && (time_.regulating(h) || time_.constrained(h)) &&
            (time_.advancing(h) || time_.federate_time(h) < *save_restore_.save.time))
            continue;
        save_restore_.save.told.insert(h);
        outbox_.send_unheld(h, wire::InitiateFederateSave{save_restore_.save.label});
        save_restore_.save.held[h];  // from now on, what is sent to h waits
    }
}

// A federate told to save stays at its time until federationSaved; one that asked to advance beyond
// time + lookahead of such a federate could never be granted, nor told. So while a timed save waits, a
// request beyond the save time is granted the save time (HLA 1.3 leaves this open).
void Federation::cap_requests_at_save_time() {
    for (const auto& [h, f] : federates_)
        if (!save_restore_.save.told.count(h)) time_.cap_request(h, *save_restore_.save.time);
}

// §4.14-4.15: federateSaveComplete / federateSaveNotComplete.
void Federation::on(FederateHandle from, const wire::FederateSaveComplete& m) {
    federate(from);
    auto& save = save_restore_.save;
    if (!save.active || !save.told.count(from)) return;  // the client raises SaveNotInitiated
    save.answered[from] = m.success;
    finish_save_if_answered();
}

// §4.16: federationSaved once every federate saved, federationNotSaved if one did not (or left), or the
// gateway could not keep the save.
void Federation::finish_save_if_answered() {
    const auto answered = outcome(save_restore_.save);
    if (!answered) return;
    if (!*answered) return finish_save({false, save_restore_.save.reason()});
    if (!save_restore_.keep(name_, save_restore_.save.label, encode_snapshot()))
        return finish_save({false, static_cast<std::uint8_t>(wire::SaveFailure::RtiUnable)});
    finish_save({});
}

void Federation::finish_save(const wire::FederationSaved& done) {
    end_run(save_restore_.save, done);
    release_time();
}

std::optional<bool> Federation::outcome(const SaveRestore::Run& run) const {
    if (!run.active) return std::nullopt;
    for (const auto& [h, f] : federates_)
        if (!run.answered.count(h)) return std::nullopt;
    bool success = !run.failed;
    for (const auto& [h, ok] : run.answered) success = success && ok;
    return success;
}

template <class R, class M>
void Federation::end_run(R& run, const M& done) {
    outbox_.holding = nullptr;
    auto held = std::move(run.held);
    run = R{};
    for (const auto& [h, f] : federates_) {
        outbox_.send(h, done);
        auto frames = held.find(h);
        if (frames != held.end()) deliver_held(h, frames->second);
    }
}

// ---- hooks ----

bool Federation::time_frozen() const { return save_restore_.time_frozen(federates_.size()); }

// Receive-order messages that time management holds (constrained, not advancing) never reach the
// outbox: what was held here would have been written at once.
void Federation::deliver_held(FederateHandle to, std::vector<std::string>& frames) {
    for (const auto& frame : frames) outbox_.send_frame(to, frame);
    frames.clear();
}

// A federate that leaves (only by a dropped connection: resigning is refused) fails the save or restore.
void Federation::save_restore_departed(FederateHandle h) {
    if (save_restore_.save.active) {
        save_restore_.save.told.erase(h);
        save_restore_.save.departed(h);
        finish_save_if_answered();
    }
    if (save_restore_.restore.active) {
        save_restore_.restore.departed(h);
        finish_restore_if_answered();
    }
}

// ---- the file ----

std::string Federation::encode_snapshot() const {
    std::string out(kFileMagic, sizeof kFileMagic);
    wire::Writer w(out);
    const auto& save = save_restore_.save;
    w(kFormatVersion, save.label, name_, fed_name_, fed_text_, next_federate_, next_object_, save.time);
    std::vector<FederateRecord> federates;
    for (const auto& [h, f] : federates_) {
        FederateRecord r;
        r.handle = h;
        r.name = f.name;
        r.published = records_of<wire::ClassAttributes>(f.declarations.published);
        r.subscribed = records_of<wire::ClassAttributes>(f.declarations.subscribed);
        r.published_interactions = handles(f.declarations.published_interactions);
        r.subscribed_interactions = handles(f.declarations.subscribed_interactions);
        r.known = handles(f.known);
        r.registration_started = handles(f.declarations.registration_started);
        r.interactions_turned_on = handles(f.declarations.interactions_turned_on);
        r.class_relevance = f.declarations.class_relevance;
        r.interaction_relevance = f.declarations.interaction_relevance;
        r.attribute_relevance = f.declarations.attribute_relevance;
        r.attribute_scope = f.declarations.attribute_scope;
        r.interaction_order = pairs(f.interaction_order);
        r.interaction_transport = pairs(f.interaction_transport);
        r.time_management = time_.save_state(h);
        auto held = save_restore_.save.held.find(h);
        if (held != save_restore_.save.held.end()) r.held_after_save = held->second;
        put_ddm(f.ddm, r);
        r.in_scope = records_of<ObjectAttributes>(f.ddm.in_scope);
        r.relevant = records_of<ObjectAttributes>(f.ddm.relevant);
        federates.push_back(std::move(r));
    }
    std::vector<DirectedRecord> directed;
    for (const auto& [h, f] : federates_) {
        const auto& d = f.declarations;
        if (d.published_directed.empty() && d.subscribed_directed.empty() && d.subscribed_directed_universally.empty())
            continue;
        directed.push_back({h, records_of<wire::ClassAttributes>(d.published_directed),
                            records_of<wire::ClassAttributes>(d.subscribed_directed),
                            records_of<wire::ClassAttributes>(d.subscribed_directed_universally)});
    }
    std::vector<ObjectRecord> objects;
    for (const auto& [oh, obj] : objects_) {
        ObjectRecord r;
        r.handle = oh;
        r.object_class = obj.object_class;
        r.name = obj.name;
        r.privilege_attribute = obj.ownership.privilege_attribute;
        r.privilege_holder = obj.ownership.privilege_holder;
        r.owners = pairs(obj.ownership.owners);
        r.order = pairs(obj.order);
        r.transport = pairs(obj.transport);
        objects.push_back(std::move(r));
    }
    w(federates, objects, directed);
    return out;
}

Federation::Snapshot Federation::decode_snapshot(const std::string& bytes) const {
    if (bytes.size() < sizeof kFileMagic || std::memcmp(bytes.data(), kFileMagic, sizeof kFileMagic) != 0)
        throw WireError("not an hlacore save (bad magic)");
    wire::Reader r(std::string_view(bytes).substr(sizeof kFileMagic), wire::MessageType::Invalid);
    std::uint32_t version = 0;
    r(version);
    if (version < kOldestReadableVersion || version > kFormatVersion)
        throw WireError("save format version " + std::to_string(version) + " (this gateway reads versions " +
                        std::to_string(kOldestReadableVersion) + " to " + std::to_string(kFormatVersion) + ")");
    Snapshot s;
    try {
        r(s.label, s.federation, s.fed_name, s.fed_text, s.next_federate, s.next_object, s.time);
        r(s.federates, s.objects);
        if (version >= 4) r(s.directed);
        if (r.remaining() != 0) r.fail("trailing bytes");
    } catch (const WireError& e) {
        // The codec names the message it was decoding; here it is the file.
        std::string what = e.what();
        const auto at = what.rfind(" in unknown message");
        throw WireError((at == std::string::npos ? what : what.substr(0, at)) + " in the save");
    }
    // Cross-references are checked here so that applying a save cannot fail halfway.
    // A federate's DDM state: regions fit the FOM's spaces, and whatever uses a region names one of the
    // federate's saved regions, in the routing space of the attribute or interaction it is used for.
    auto check_saved_ddm = [&](const FederateRecord& f, const std::map<std::uint32_t, std::uint32_t>& objects) {
        const std::string whose = " of federate '" + f.name + "'";
        std::map<std::uint32_t, fom::Handle> spaces;  // region -> space
        for (const auto& [region, space, bounds] : f.regions) {
            if (region == 0 || region > f.last_region || !spaces.emplace(region, space).second)
                throw WireError("bad region handle " + std::to_string(region) + whose);
            Region::from_bounds(fom_, space, bounds);  // the space exists, the bounds fit its dimensions
        }
        auto space_of = [&](std::uint32_t region) {
            auto it = spaces.find(region);
            if (it == spaces.end()) throw WireError("unsaved region " + std::to_string(region) + whose);
            return it->second;
        };
        auto check_attribute_space = [&](const fom::ObjectClass& cls, fom::Handle attr, std::uint32_t region) {
            const auto* a = cls.attribute(attr);
            const auto* space = a ? fom_.find_space(a->space) : nullptr;
            if (!space || space->handle != space_of(region))
                throw WireError("region " + std::to_string(region) + whose + " is not in the routing space of an "
                                "attribute of class '" + cls.qualified_name + "'");
        };
        for (const auto& [cls_handle, region, attrs] : f.region_subscriptions) {
            const auto& cls = object_class(cls_handle);
            check_attributes(cls, attrs);
            for (auto attr : attrs) check_attribute_space(cls, attr, region);
        }
        for (const auto& [ic, region] : f.region_interaction_subscriptions) {
            const auto* space = fom_.find_space(interaction_class(ic).space);
            if (!space || space->handle != space_of(region))
                throw WireError("region " + std::to_string(region) + whose + " is not in the routing space of "
                                "interaction class " + std::to_string(ic));
        }
        auto class_of = [&](std::uint32_t object) -> const fom::ObjectClass& {
            auto it = objects.find(object);
            if (it == objects.end()) throw WireError("DDM state" + whose + " names an unsaved object");
            return object_class(it->second);
        };
        for (const auto& [object, attribute, region] : f.update_regions)
            check_attribute_space(class_of(object), attribute, region);
        for (const auto* advised : {&f.in_scope, &f.relevant})
            for (const auto& [object, attrs] : *advised) check_attributes(class_of(object), attrs);
    };
    std::set<std::uint32_t> handles_seen;
    std::set<std::string> names_seen;
    for (const auto& f : s.federates) {
        if (f.handle == 0 || !handles_seen.insert(f.handle).second || !names_seen.insert(f.name).second)
            throw WireError("duplicate federate '" + f.name + "'");
        for (const auto& d : f.published) check_attributes(object_class(d.object_class), d.attributes);
        for (const auto& d : f.subscribed) check_attributes(object_class(d.object_class), d.attributes);
        for (auto ic : f.published_interactions) interaction_class(ic);
        for (auto ic : f.subscribed_interactions) interaction_class(ic);
        if (f.handle >= s.next_federate) throw WireError("federate handle beyond the saved next handle");
    }
    for (const auto& d : s.directed) {
        if (!handles_seen.count(d.federate)) throw WireError("directed interactions of an unknown federate");
        for (const auto* declared : {&d.published, &d.subscribed, &d.universally}) {
            for (const auto& [oc, interactions] : *declared) {
                object_class(oc);
                for (auto ic : interactions) interaction_class(ic);
            }
        }
    }
    std::map<std::uint32_t, std::uint32_t> objects_seen;  // object -> class
    std::set<std::string> object_names;
    for (const auto& o : s.objects) {
        if (!object_names.insert(o.name).second) throw WireError("duplicate object name '" + o.name + "'");
        check_delivery_values(o.order, "object '" + o.name + "'");
        check_delivery_values(o.transport, "object '" + o.name + "'");
        const auto& cls = object_class(o.object_class);
        for (const auto& [attr, owner] : o.owners) {
            if (!cls.attribute(attr) || !handles_seen.count(owner)) throw WireError("bad owner of object '" + o.name + "'");
        }
        if (o.handle == 0 || o.handle >= s.next_object || !objects_seen.emplace(o.handle, o.object_class).second)
            throw WireError("bad handle of object '" + o.name + "'");
    }
    for (const auto& f : s.federates) {
        for (auto oh : f.known)
            if (!objects_seen.count(oh)) throw WireError("federate '" + f.name + "' knows an unsaved object");
        for (const auto& m : f.time_management.tso) {
            if (!handles_seen.count(m.sender)) throw WireError("queued message from an unsaved federate");
            check_frame(m.frame);
        }
        for (const auto& frame : f.time_management.held_ro) check_frame(frame);
        for (const auto& frame : f.held_after_save) check_frame(frame);
        check_delivery_values(f.interaction_order, "federate '" + f.name + "'");
        check_delivery_values(f.interaction_transport, "federate '" + f.name + "'");
        check_saved_ddm(f, objects_seen);
    }
    return s;
}

// ---- restore (HLA 1.3 §4.17-4.22) ----

void Federation::request_restore(FederateHandle from, const std::string& label) {
    federate(from);
    check_membership_change("requestFederationRestore");
    auto fail = [&](const std::string& reason) {
        outbox_.send(from, wire::RestoreRequestAnswer{label, false, reason});
    };
    std::string bytes;
    std::string source = "this gateway's memory";
    if (auto kept = save_restore_.saves.find(label); kept != save_restore_.saves.end()) {
        bytes = kept->second;
    } else if (!save_restore_.dir.empty()) {
        source = save_restore_.file(name_, label);
        std::ifstream in(source, std::ios::binary);
        if (!in) return fail("no save labelled '" + label + "': cannot open " + source + ": " + std::strerror(errno));
        std::ostringstream text;
        text << in.rdbuf();
        bytes = text.str();
    } else {
        return fail("no save labelled '" + label + "' in this gateway's memory (rtig keeps saves in files only "
                    "with --save-dir)");
    }
    Snapshot snap;
    try {
        snap = decode_snapshot(bytes);
    } catch (const WireError& e) {
        return fail("the save in " + source + " is unusable: " + e.what());
    }
    // The FOM may have been extended since the save (modules added at join): its handles kept their meaning.
    if (!fom::extends(fed_text_, snap.fed_text)) return fail("the save was made with another FOM (" + snap.fed_name + ")");
    std::map<std::string, FederateHandle> joined;
    std::set<std::string> joined_names, saved_names;
    for (const auto& [h, f] : federates_) {
        joined[f.name] = h;
        joined_names.insert(f.name);
    }
    for (const auto& f : snap.federates) saved_names.insert(f.name);
    if (joined_names != saved_names)
        return fail("the federates joined now (" + join_names(joined_names) + ") are not those of the save (" +
                    join_names(saved_names) + ")");

    // §4.18-4.19: the requester hears it succeeded, every federate that the restore begins.
    outbox_.send(from, wire::RestoreRequestAnswer{label, true, ""});
    for (const auto& [h, f] : federates_) outbox_.send(h, wire::FederationRestoreBegun{});

    std::map<FederateHandle, FederateHandle> new_handles;
    for (const auto& f : snap.federates) new_handles[joined.at(f.name)] = f.handle;
    federates_.clear();
    objects_.clear();
    object_names_.clear();
    sync_points_.clear();  // their members' handles are gone
    reservations_.clear();
    routed_.clear();
    time_ = TimeManager{};
    save_restore_.restore = SaveRestore::Run{};
    save_restore_.restore.active = true;
    save_restore_.restore.label = label;
    std::map<FederateHandle, std::uint64_t> last_serial;
    for (auto& r : snap.federates) {
        FederateState& f = federates_[r.handle];
        f.name = r.name;
        for (const auto& [cls, attrs] : r.published) f.declarations.published[cls] = std::set<fom::Handle>(attrs.begin(), attrs.end());
        for (const auto& [cls, attrs] : r.subscribed) f.declarations.subscribed[cls] = std::set<fom::Handle>(attrs.begin(), attrs.end());
        f.declarations.published_interactions.insert(r.published_interactions.begin(), r.published_interactions.end());
        f.declarations.subscribed_interactions.insert(r.subscribed_interactions.begin(), r.subscribed_interactions.end());
        f.known.insert(r.known.begin(), r.known.end());
        f.declarations.registration_started.insert(r.registration_started.begin(), r.registration_started.end());
        f.declarations.interactions_turned_on.insert(r.interactions_turned_on.begin(), r.interactions_turned_on.end());
        f.declarations.class_relevance = r.class_relevance;
        f.declarations.interaction_relevance = r.interaction_relevance;
        f.declarations.attribute_relevance = r.attribute_relevance;
        f.declarations.attribute_scope = r.attribute_scope;
        for (const auto& [ic, v] : r.interaction_order) f.interaction_order[ic] = static_cast<fom::Order>(v);
        for (const auto& [ic, v] : r.interaction_transport) f.interaction_transport[ic] = static_cast<fom::Transport>(v);
        for (const auto& m : r.time_management.tso) last_serial[m.sender] = std::max(last_serial[m.sender], m.serial);
        time_.restore_state(r.handle, std::move(r.time_management));
        for (const auto& [region, space, bounds] : r.regions) f.ddm.regions[region] = Region::from_bounds(fom_, space, bounds);
        for (const auto& [cls, region, attrs] : r.region_subscriptions)
            f.ddm.object_subscriptions[cls][region] = std::set<fom::Handle>(attrs.begin(), attrs.end());
        for (const auto& [ic, region] : r.region_interaction_subscriptions) f.ddm.interaction_subscriptions[ic].insert(region);
        for (const auto& [object, attribute, region] : r.update_regions) f.ddm.update_regions[object][attribute].insert(region);
        for (const auto& [object, attrs] : r.in_scope) f.ddm.in_scope[object].insert(attrs.begin(), attrs.end());
        for (const auto& [object, attrs] : r.relevant) f.ddm.relevant[object].insert(attrs.begin(), attrs.end());
        f.ddm.last_region = r.last_region;
        // What the save held back is delivered after federationRestored, as it was after federationSaved.
        if (!r.held_after_save.empty()) save_restore_.restore.held[r.handle] = std::move(r.held_after_save);
    }
    for (const auto& d : snap.directed) {
        auto& f = federates_.at(d.federate).declarations;
        auto put = [](auto& declared, const auto& records) {
            for (const auto& [oc, ics] : records) declared[oc] = std::set<fom::Handle>(ics.begin(), ics.end());
        };
        put(f.published_directed, d.published);
        put(f.subscribed_directed, d.subscribed);
        put(f.subscribed_directed_universally, d.universally);
    }
    for (const auto& r : snap.objects) {
        ObjectInstance& obj = objects_[r.handle];
        obj.object_class = r.object_class;
        obj.name = r.name;
        obj.ownership.privilege_attribute = r.privilege_attribute;
        obj.ownership.privilege_holder = federates_.count(r.privilege_holder) ? r.privilege_holder : 0;
        for (const auto& [attr, owner] : r.owners) obj.ownership.owners[attr] = owner;
        for (const auto& [attr, v] : r.order) obj.order[attr] = static_cast<fom::Order>(v);
        for (const auto& [attr, v] : r.transport) obj.transport[attr] = static_cast<fom::Transport>(v);
        object_names_[r.name] = r.handle;
    }
    // Handles given out since the save are never reused.
    next_federate_ = std::max(next_federate_, static_cast<FederateHandle>(snap.next_federate));
    next_object_ = std::max(next_object_, static_cast<ObjectHandle>(snap.next_object));
    outbox_.rehandle(new_handles);
    count_scope_watchers();

    // §4.20 initiateFederateRestore, with what the client mirrors of the restored federate.
    for (const auto& [h, f] : federates_) {
        wire::InitiateFederateRestore m;
        m.label = label;
        m.federate = h;
        wire::RestoredState& state = m.state.edit();
        state.time_state = time_.save_state(h).time;
        state.next_serial = last_serial[h];
        state.published = records_of<wire::ClassAttributes>(f.declarations.published);
        state.subscribed = records_of<wire::ClassAttributes>(f.declarations.subscribed);
        state.published_interactions = handles(f.declarations.published_interactions);
        state.subscribed_interactions = handles(f.declarations.subscribed_interactions);
        state.published_directed = records_of<wire::ClassAttributes>(f.declarations.published_directed);
        state.subscribed_directed = records_of<wire::ClassAttributes>(f.declarations.subscribed_directed);
        state.subscribed_directed_universally =
            records_of<wire::ClassAttributes>(f.declarations.subscribed_directed_universally);
        for (ObjectHandle oh : f.known) {
            const ObjectInstance& obj = objects_.at(oh);
            fom::Handle as = obj.object_class;
            if (!f.declarations.published.count(as)) {
                const fom::Handle subscribed_as = known_class(f, as);
                if (subscribed_as) as = subscribed_as;
            }
            wire::Handles owned;
            for (const auto& [attr, owner] : obj.ownership.owners)
                if (owner == h) owned.push_back(attr);
            state.objects.push_back({oh, as, obj.name, std::move(owned), obj.ownership.deleter() == h});
        }
        put_ddm(f.ddm, state);
        outbox_.send(h, m);
    }
    // Until federationRestored, what is sent to the federates waits.
    for (const auto& [h, f] : federates_) save_restore_.restore.held[h];
    outbox_.holding = &save_restore_.restore.held;
}

// §4.21: federateRestoreComplete / federateRestoreNotComplete.
void Federation::on(FederateHandle from, const wire::FederateRestoreComplete& m) {
    federate(from);
    auto& restore = save_restore_.restore;
    if (!restore.active || restore.answered.count(from)) return;  // the client raises RestoreNotRequested
    restore.answered[from] = m.success;
    finish_restore_if_answered();
}

// §4.22: federationRestored, or federationNotRestored if a federate could not restore (or left); the
// gateway's state is the save's either way.
void Federation::finish_restore_if_answered() {
    const auto answered = outcome(save_restore_.restore);
    if (!answered) return;
    finish_restore({*answered, *answered ? std::uint8_t{0} : save_restore_.restore.reason()});
}

void Federation::finish_restore(const wire::FederationRestored& done) {
    end_run(save_restore_.restore, done);
    update_advisories();
    count_scope_watchers();
    refresh_scope();  // from the scope and relevance already announced in the save
    release_time();
}

// ---- IEEE 1516-2010's aborts (an aborted restore leaves the gateway's state the save's, as a failed one does) ----

void Federation::abort_save(FederateHandle from) {
    federate(from);
    save_restore_.check_saving();
    finish_save({false, static_cast<std::uint8_t>(wire::SaveFailure::Aborted)});
}

void Federation::abort_restore(FederateHandle from) {
    federate(from);
    save_restore_.check_restoring();
    finish_restore({false, static_cast<std::uint8_t>(wire::RestoreFailure::Aborted)});
}

// ---- introspection ----

void Federation::write_save_status(std::string& out) const {
    out += ",\"save_restore\":{\"state\":";
    if (save_restore_.restore.active) {
        out += "\"restoring\",\"label\":";
        json_string(out, save_restore_.restore.label);
    } else if (save_restore_.save.active) {
        out += save_restore_.save.told.size() >= federates_.size() ? "\"saving\"" : "\"waiting for the save time\"";
        out += ",\"label\":";
        json_string(out, save_restore_.save.label);
        out += ",\"time\":";
        if (save_restore_.save.time) {
            json_number(out, *save_restore_.save.time);
        } else {
            out += "null";
        }
        out += ",\"told\":";
        json_array(out, save_restore_.save.told, [&](FederateHandle h) { out += std::to_string(h); });
    } else {
        out += "\"idle\"";
    }
    if (save_restore_.restore.active || save_restore_.save.active) {
        out += ",\"answered\":";
        json_array(out, save_restore_.restore.active ? save_restore_.restore.answered : save_restore_.save.answered,
                   [&](const auto& answer) { out += std::to_string(answer.first); });
    }
    out += ",\"saves\":";
    json_array(out, save_restore_.saves, [&](const auto& save) { json_string(out, save.first); });
    out += ",\"save_dir\":";
    json_string(out, save_restore_.dir);
    out += ",\"save_error\":";
    json_string(out, save_restore_.error);
    out += '}';
}

void Federation::write_instances(std::string& out) const {
    out += ",\"instances\":";
    json_array(out, objects_, [&](const auto& object) {
        const auto& [oh, obj] = object;
        const auto* cls = fom_.object_class(obj.object_class);
        out += "{\"handle\":" + std::to_string(oh) + ",\"name\":";
        json_string(out, obj.name);
        out += ",\"class\":";
        json_string(out, cls ? cls->qualified_name : std::to_string(obj.object_class));
        out += ",\"owners\":{";
        bool first_owner = true;
        for (const auto& [attr, owner] : obj.ownership.owners) {
            if (!first_owner) out += ',';
            first_owner = false;
            const auto* a = cls ? cls->attribute(attr) : nullptr;
            json_string(out, a ? a->name : std::to_string(attr));
            out += ':' + std::to_string(owner);
        }
        out += "}}";
    });
}

}  // namespace hlacore
