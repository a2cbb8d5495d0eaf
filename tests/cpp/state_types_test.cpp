// Unit tests of the gateway's service-group state types (cpp/rti/server/<group>.hpp) on their own, without
// a federation: regions and their overlap, a federate's DDM state, attribute ownership, save/restore, held
// messages parked beyond a federate's share and the spill files they go to; and
// the connection's read buffer and the values a federate decodes as views into it (cpp/rti/wire/).
// Built by ./scripts/test.sh (target state_types_test, with the sanitizers) and run by
// tests/rti/test_state_types.py; prints "ok <case>" per case, exits non-zero at the first failure.
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "rti/exceptions.hpp"
#include "rti/server/ownership.hpp"
#include "rti/server/regions.hpp"
#include "rti/server/save_restore.hpp"
#include "rti/server/spill.hpp"
#include "rti/server/time_manager.hpp"
#include "rti/wire/read_buffer.hpp"
#include "rti/wire/splices.hpp"

using namespace hlacore;

namespace {

int failures = 0;

void check(bool condition, const char* what, int line) {
    if (condition) return;
    std::printf("FAILED line %d: %s\n", line, what);
    ++failures;
}
#define CHECK(condition) check((condition), #condition, __LINE__)

// True when `f` throws E whose message contains `text`.
template <class E>
bool throws(const std::function<void()>& f, const std::string& text = "") {
    try {
        f();
    } catch (const E& e) {
        return std::string(e.what()).find(text) != std::string::npos;
    } catch (...) {
        return false;
    }
    return false;
}

const char* kFed = R"((FED (Federation T) (FEDversion v1.3)
 (spaces (space Geo (dimension X) (dimension Y)) (space Point))
 (objects (class ObjectRoot (attribute privilegeToDelete reliable timestamp) (class RTIprivate)))
 (interactions (class InteractionRoot reliable receive (class RTIprivate reliable receive)))))";

Region box(const fom::Fom& fom, std::uint32_t x0, std::uint32_t x1, std::uint32_t y0, std::uint32_t y1) {
    return Region::from_bounds(fom, fom.find_space("Geo")->handle, {x0, x1, y0, y1});
}

void regions_from_bounds(const fom::Fom& fom) {
    const fom::Handle geo = fom.find_space("Geo")->handle;
    const Region r = Region::from_bounds(fom, geo, {0, 5, 10, 20, 7, 9, 1, 1});
    CHECK(r.space == geo && r.extents.size() == 2 && r.extents[1][1] == Region::Range(1, 1));
    CHECK(throws<wire::WireError>([&] { Region::from_bounds(fom, 999, {}); }, "not defined in the FOM"));
    CHECK(throws<wire::WireError>([&] { Region::from_bounds(fom, geo, {0, 5, 1}); }, "do not match the dimensions"));
    CHECK(throws<wire::WireError>([&] { Region::from_bounds(fom, geo, {}); }, "do not match the dimensions"));
    CHECK(throws<wire::WireError>([&] { Region::from_bounds(fom, geo, {6, 5, 0, 0}); }, "lower bound above upper"));
    // A space without dimensions has one extent covering it, and refuses bounds.
    const fom::Handle point = fom.find_space("Point")->handle;
    CHECK(Region::from_bounds(fom, point, {}).extents.size() == 1);
    CHECK(throws<wire::WireError>([&] { Region::from_bounds(fom, point, {0, 1}); }, "has no dimensions"));
}

void regions_overlap(const fom::Fom& fom) {
    CHECK(box(fom, 0, 5, 0, 5).overlaps(box(fom, 5, 9, 5, 9)));   // closed ranges: touching overlaps
    CHECK(!box(fom, 0, 5, 0, 5).overlaps(box(fom, 6, 9, 0, 5)));  // apart in X
    CHECK(!box(fom, 0, 5, 0, 5).overlaps(box(fom, 0, 5, 6, 9)));  // apart in Y only
    const fom::Handle geo = fom.find_space("Geo")->handle;
    const Region two = Region::from_bounds(fom, geo, {0, 1, 0, 1, 8, 9, 8, 9});  // some extent of each is enough
    CHECK(two.overlaps(box(fom, 9, 9, 9, 9)) && box(fom, 9, 9, 9, 9).overlaps(two));
    CHECK(!two.overlaps(box(fom, 4, 5, 4, 5)));
}

void federate_regions(const fom::Fom& fom) {
    FederateRegions ddm;
    CHECK(throws<wire::WireError>([&] { ddm.create(0, box(fom, 0, 1, 0, 1)); }, "is 0 or already in use"));
    ddm.create(7, box(fom, 0, 5, 0, 5));
    ddm.create(3, box(fom, 6, 9, 6, 9));
    CHECK(ddm.last_region == 7);
    CHECK(throws<wire::WireError>([&] { ddm.create(3, box(fom, 0, 1, 0, 1)); }, "already in use"));
    CHECK(throws<wire::WireError>([&] { ddm.at(4); }, "region 4 is not known"));

    const fom::Handle cls = 10, attr = 20, other_attr = 21, ic = 30;
    const ObjectHandle object = 40;
    ddm.object_subscriptions[cls][7] = {attr};
    ddm.interaction_subscriptions[ic] = {3};
    associate_region(ddm.update_regions, object, attr, 3, false);
    CHECK(!ddm.update_regions_of(object, attr).is_default());
    CHECK(ddm.update_regions_of(object, other_attr).is_default());
    // Subscribed through region 7: an update in the default region or an overlapping one reaches it.
    const Region near = box(fom, 5, 6, 5, 6), far = box(fom, 8, 9, 8, 9);
    CHECK(ddm.subscribed(cls, attr, nullptr) && ddm.subscribed(cls, attr, &near));
    CHECK(!ddm.subscribed(cls, attr, &far) && !ddm.subscribed(cls, other_attr, nullptr));
    const Region corner = box(fom, 0, 1, 0, 1);
    CHECK(ddm.subscribed_interaction(ic, &far) && !ddm.subscribed_interaction(ic, &corner));
    CHECK(ddm.subscribed_interaction(ic, nullptr) && !ddm.subscribed_interaction(ic + 1, nullptr));
    // Region 3 (6-9) misses region 7 (0-5); with region 7 among its update regions the attribute is in scope.
    CHECK(!ddm.subscribed(cls, attr, ddm.update_regions_of(object, attr)));
    associate_region(ddm.update_regions, object, attr, 7, true);  // IEEE 1516-2010: adds
    CHECK(ddm.update_regions.at(object).at(attr) == std::set<RegionHandle>({3, 7}));
    CHECK(ddm.subscribed(cls, attr, ddm.update_regions_of(object, attr)));
    associate_region(ddm.update_regions, object, attr, 3, false);  // HLA 1.3: replaces
    CHECK(ddm.update_regions.at(object).at(attr) == std::set<RegionHandle>({3}));
    associate_region(ddm.update_regions, object, attr, 7, true);
    associate_region(ddm.update_regions, object, other_attr, 7, true);
    CHECK(!unassociate_region(ddm.update_regions, object, 99, {}));
    CHECK(unassociate_region(ddm.update_regions, object, 7, {attr}));  // the pair named only
    CHECK(ddm.update_regions.at(object).at(attr) == std::set<RegionHandle>({3}));
    CHECK(ddm.update_regions.at(object).at(other_attr) == std::set<RegionHandle>({7}));
    CHECK(unassociate_region(ddm.update_regions, object, 7, {}));  // HLA 1.3: every attribute of the object
    CHECK(!ddm.update_regions.at(object).count(other_attr));
    // The sent regions of an interaction: any one overlapping a subscription region is enough.
    const std::set<RegionHandle> sent{3, 7};
    CHECK(ddm.subscribed_interaction(ic, SentRegions{ddm, sent}) && !ddm.subscribed_interaction(ic + 1, SentRegions{ddm, sent}));
    CHECK(ddm.subscribed_interaction(ic, SentRegions{}));

    CHECK(!ddm.unsubscribe(ddm.object_subscriptions, cls, 3));  // nothing through region 3
    CHECK(throws<wire::WireError>([&] { ddm.unsubscribe(ddm.object_subscriptions, cls, 99); }, "not known"));
    CHECK(ddm.unsubscribe(ddm.object_subscriptions, cls, 7) && ddm.object_subscriptions.empty());

    // Deleting a region takes what refers to it along.
    ddm.object_subscriptions[cls][3] = {attr};
    ddm.erase(3);
    CHECK(!ddm.regions.count(3) && ddm.object_subscriptions.empty() && ddm.interaction_subscriptions.empty());
    CHECK(!ddm.update_regions.count(object) && ddm.update_regions_of(object, attr).is_default());
    CHECK(ddm.last_region == 7);  // kept: a restored client never reuses a number
}

void attribute_ownership() {
    AttributeOwnership o;
    CHECK(o.owner(5) == 0 && o.deleter() == 0);
    o.privilege_holder = 2;  // no privilegeToDelete attribute in the FOM: the registrant may delete
    CHECK(o.deleter() == 2);
    o.privilege_attribute = 1;  // with one: its owner may, nobody while it is unowned
    CHECK(o.deleter() == 0);
    o.owners[1] = 3;
    o.owners[5] = 4;
    CHECK(o.deleter() == 3 && o.owner(5) == 4 && o.owner(6) == 0);
}

void save_restore_runs() {
    SaveRestore sr;
    sr.check_idle("joinFederationExecution");
    sr.check_not_restoring();
    CHECK(!sr.restoring(1) && !sr.time_frozen(2));
    sr.save.active = true;
    sr.save.label = "s1";
    CHECK(throws<RtiError>([&] { sr.check_idle("resignFederationExecution"); }, "save 's1' is in progress"));
    sr.save.told = {1};
    CHECK(!sr.time_frozen(2));  // one of two federates still runs
    sr.save.told.insert(2);
    CHECK(sr.time_frozen(2));
    sr.save = SaveRestore::SaveRun{};
    sr.restore.active = true;
    sr.restore.label = "s1";
    sr.restore.answered[1] = true;
    CHECK(throws<RtiError>([&] { sr.check_idle("requestFederationSave"); }, "restore 's1' is in progress"));
    CHECK(throws<RtiError>([&] { sr.check_not_restoring(); }, "the federation restore 's1' is in progress"));
    CHECK(!sr.restoring(1) && sr.restoring(2) && sr.time_frozen(5));
    sr.restore.departed(1);
    CHECK(sr.restore.failed && !sr.restore.answered.count(1));
}

void save_restore_files() {
    SaveRestore sr;
    CHECK(sr.keep("fed", "s", "bytes") && sr.saves.at("s") == "bytes");  // no directory: memory only
    sr.dir = "/saves";
    // No label reaches outside the directory; "--" separates the federation from the label.
    CHECK(sr.file("my fed", "../x") == "/saves/my%20fed--%2E.%2Fx.hlasave");
    sr.dir = "/proc/hlacore-no-such-dir";  // cannot be created
    CHECK(!sr.keep("fed", "t", "bytes") && !sr.saves.count("t"));
    CHECK(sr.error.find("cannot write /proc/hlacore-no-such-dir/fed--t.hlasave") == 0);
}

// Appends `bytes` to `in` as a socket read of them would.
void receive(wire::ReadBuffer& in, const std::string& bytes) {
    std::memcpy(in.room(bytes.size()), bytes.data(), bytes.size());
    in.commit(bytes.size());
}

std::string frame_header(std::uint32_t length) {
    return std::string(reinterpret_cast<const char*>(&length), 4);
}

void read_buffer() {
    wire::ReadBuffer in;
    CHECK(in.empty() && in.wanted(1u << 30) == wire::ReadBuffer::kChunk);
    // A small frame and the start of the next: the rest of the first is used, the partial one stays.
    receive(in, frame_header(2) + "ab" + frame_header(10) + "xy");
    CHECK(in.unread().size() == 12);
    in.consume(6);
    CHECK(in.unread() == frame_header(10) + "xy");
    // Its header is in and it is small: a chunk is asked for. Reading more moves the partial frame down
    // into the room the used one left, then into a larger block.
    CHECK(in.wanted(1u << 30) == wire::ReadBuffer::kChunk);
    receive(in, "cdef");
    CHECK(in.capacity() == 12 && in.unread() == frame_header(10) + "xycdef");
    receive(in, "ghij");
    CHECK(in.capacity() == 24 && in.unread() == frame_header(10) + "xycdefghij");
    in.consume(14);
    CHECK(in.empty());
    // A large frame asks for its whole rest at once, and the block is that size exactly.
    const std::size_t large = 3 * wire::ReadBuffer::kChunk;
    receive(in, frame_header(static_cast<std::uint32_t>(large)) + "12");
    CHECK(in.wanted(1u << 30) == large - 2);
    in.room(in.wanted(1u << 30));
    CHECK(in.capacity() == 4 + large);
    CHECK(!in.holds_large_frame());
    // Its last bytes, fewer than a chunk, are asked for exactly: a chunk would not fit and would move it all.
    receive(in, std::string(large - 12, 'z'));
    CHECK(in.wanted(1u << 30) == 10);
    receive(in, std::string(10, 'z'));
    CHECK(in.unread().size() == 4 + large && in.unread().substr(4, 3) == "12z" && in.capacity() == 4 + large);
    // Whole, it is decoded before anything more is read; small frames, however many, never hold reading back.
    CHECK(in.holds_large_frame());
    wire::ReadBuffer smalls;
    receive(smalls, frame_header(2) + "ab" + std::string(2 * wire::ReadBuffer::kChunk, 's'));
    CHECK(!smalls.holds_large_frame());
    // A length over the limit asks for a chunk only: the frame is refused when decoded, nothing reserved.
    CHECK(in.wanted(16) == wire::ReadBuffer::kChunk);
    in.consume(4 + large);
    in.release_above(wire::ReadBuffer::kChunk);
    CHECK(in.capacity() == 0 && in.empty());
}

// A federate decodes large values as views into the block it read them into (wire::Value); the block is not
// written again while one of them lives, and is read into again once they are gone.
void viewed_values() {
    wire::ReflectAttributes r;
    const std::string large(wire::kSplicedValueBytes, 'v');
    r.values.emplace_back(1, large);
    r.values.emplace_back(2, std::string("small"));
    std::string frame;
    wire::encode(frame, r);
    wire::ReadBuffer in;
    // Decodes the frame at the start of `in` as the client does, with the block it lies in.
    const auto decode_next = [&in, &frame] {
        const std::shared_ptr<const char[]> block = in.share();
        wire::Frame f;
        CHECK(wire::next_frame(in.unread(), f) == frame.size());
        f.block = &block;
        wire::Message m = wire::decode(f);
        in.consume(frame.size());
        return m;
    };
    receive(in, frame);  // a large frame gets a block of its size
    const char* first = in.share().get();
    auto m1 = std::make_unique<wire::Message>(decode_next());
    const auto& values = std::get<wire::ReflectAttributes>(*m1).values;
    CHECK(values.at(0).second.in_block() && values.at(0).second == large);
    CHECK(values.at(0).second.data() > first && values.at(0).second.data() < first + frame.size());
    CHECK(!values.at(1).second.in_block() && values.at(1).second == "small");
    // Without a block (datagrams, the gateway's own decoding), every value is its own string.
    wire::Frame plain;
    CHECK(wire::next_frame(frame, plain) == frame.size());
    CHECK(!std::get<wire::ReflectAttributes>(wire::decode(plain)).values.at(0).second.in_block());
    // The next frame goes to another block while the value lives, which still reads as it was.
    receive(in, frame);
    CHECK(in.share().get() != first && values.at(0).second == large);
    const wire::Message m2 = decode_next();
    // Once the first value is gone, the frame after (the second block held by m2's value) reuses the first.
    m1.reset();
    receive(in, frame);
    CHECK(in.share().get() == first);
    CHECK(std::get<wire::ReflectAttributes>(m2).values.at(0).second == large);
}

// The pieces of a stream with splices: in order, and never more than there is room for.
void splices_gather() {
    const std::string buffer = "headAtailBend";  // splices go in at 4 ("one") and 9 ("two")
    const std::vector<wire::Splice> splices = {{4, "one"}, {9, "two"}};
    const auto stream = [&](const iovec* pieces, std::size_t n) {
        std::string s;
        for (std::size_t i = 0; i < n; ++i) s.append(static_cast<const char*>(pieces[i].iov_base), pieces[i].iov_len);
        return s;
    };
    iovec pieces[5];
    CHECK(stream(pieces, wire::gather(buffer, 0, splices, pieces, 5)) == "headoneAtailtwoBend");
    CHECK(stream(pieces, wire::gather(buffer, 2, splices, pieces, 5)) == "adoneAtailtwoBend");  // from an offset
    // Room for 4: the second splice would leave no room for what follows it, so the pieces end before it.
    CHECK(wire::gather(buffer, 0, splices, pieces, 4) == 3 && stream(pieces, 3) == "headoneAtail");
    CHECK(wire::gather(buffer, 0, splices, pieces, 1) == 1 && stream(pieces, 1) == "head");
    // A splice at the buffer's end, and one at the start: no empty pieces.
    const std::vector<wire::Splice> edges = {{0, "first"}, {buffer.size(), "last"}};
    const std::size_t n = wire::gather(buffer, 0, edges, pieces, 5);
    CHECK(n == 3 && stream(pieces, n) == "first" + buffer + "last");
    // Encoding through a SplicingOutput leaves the large value out of the buffer and says where it goes.
    wire::ReflectAttributes r;
    r.values.emplace_back(1, std::string(wire::kSplicedValueBytes, 'v'));
    std::string frame, rest;
    wire::encode(frame, r);
    std::vector<wire::Splice> noted;
    wire::SplicingOutput out{rest, [&noted](std::size_t at, std::string_view bytes) {
                                 noted.push_back({at, bytes});
                                 return true;
                             }};
    wire::encode_to(out, r);
    CHECK(noted.size() == 1 && rest.size() + wire::kSplicedValueBytes == frame.size());
    std::vector<iovec> all(2 * noted.size() + 1);
    CHECK(stream(all.data(), wire::gather(rest, 0, noted, all.data(), all.size())) == frame);
}

// A parking in memory, to see what the time manager parks and takes back.
struct MapParking : FrameParking {
    std::map<std::uint64_t, std::string> kept;
    std::uint64_t next = 0;
    int forgotten = 0;
    std::optional<std::uint64_t> park(std::uint32_t, std::string_view frame) override {
        kept[next] = std::string(frame);
        return next++;
    }
    std::string unpark(std::uint32_t, std::uint64_t ticket, std::uint32_t size, bool keep) override {
        std::string frame = kept.at(ticket);
        check(frame.size() == size, "the parked size", __LINE__);
        if (!keep) kept.erase(ticket);
        return frame;
    }
    void forget(std::uint32_t) override {
        kept.clear();
        ++forgotten;
    }
};

void time_parking() {
    MapParking parking;
    TimeManager time;
    time.attach_parking(&parking, 1000);
    for (std::uint32_t f : {1u, 2u}) time.add_federate(f);
    time.enable_regulation(1, 0, 1);
    time.enable_constrained(2);
    time.release();
    // Out of timestamp order, 100 frames of 100 bytes: beyond 1000 bytes held in memory, the rest parked.
    for (std::uint64_t i = 0; i < 100; ++i) {
        const double t = 1 + static_cast<double>((i * 37) % 100);
        time.enqueue_tso(2, t, 1, i, std::make_shared<std::string>(std::string(99, 'a') + std::to_string(i % 10)));
    }
    CHECK(!parking.kept.empty() && parking.kept.size() < 100);
    CHECK(time.held_bytes(2) < 100 * 100);  // the parked ones weigh their entry only
    const auto saved = time.save_state(2);   // reads the parked frames and leaves them parked
    CHECK(saved.tso.size() == 100 && !parking.kept.empty());
    time.request(1, AdvanceKind::TimeAdvanceRequest, 200);
    time.request(2, AdvanceKind::TimeAdvanceRequest, 200);
    std::vector<std::string> delivered;
    for (auto& r : time.release())
        if (r.federate == 2)
            for (auto& frame : r.frames) delivered.push_back(*frame);
    CHECK(delivered.size() == 100 && parking.kept.empty());  // all taken back, none left parked
    bool in_order = delivered.size() == saved.tso.size();
    for (std::size_t k = 0; in_order && k < delivered.size(); ++k) in_order = delivered[k] == saved.tso[k].frame;
    CHECK(in_order);
    // Held receive-order messages park the same way; leaving gives up what is parked.
    time.request(1, AdvanceKind::TimeAdvanceRequest, 300);
    time.release();
    for (int i = 0; i < 50; ++i) time.enqueue_receive_order(2, std::string(100, 'r'));
    CHECK(!parking.kept.empty());
    time.remove_federate(2);
    CHECK(parking.forgotten == 1 && parking.kept.empty());
}

void spill_files() {
    SpillBudget budget;
    budget.limit = 1 << 20;
    {
        SpillFile fifo(budget);
        CHECK(fifo.append("hello ") == 0 && fifo.append("world") == 6 && budget.used == 11);
        std::string out;
        CHECK(fifo.read(out, 8) == 8 && out == "hello wo" && fifo.size() == 3);
        CHECK(fifo.read(out, 100) == 3 && out == "hello world");
        CHECK(fifo.size() == 0 && budget.used == 0);  // drained: all given back
        SpillFile parked(budget);
        const auto a = parked.append("first"), b = parked.append("second");
        std::string frame;
        parked.read_at(b, 6, frame);
        parked.release(6);
        CHECK(frame == "second" && budget.used == 11);
        frame.clear();
        parked.read_at(a, 5, frame);
        parked.release(5);
        CHECK(frame == "first" && budget.used == 0);
        fifo.append(std::string(600000, 'x'));
        CHECK(throws<SpillError>([&] { parked.append(std::string(600000, 'y')); }, "is spent"));
    }
    CHECK(budget.used == 0);  // the files' disk goes with them
    budget.directory = "/no/such/directory";
    CHECK(throws<SpillError>([&] { SpillFile{budget}; }, "No such file or directory"));
}

}  // namespace

int main() {
    const fom::Fom fom = fom::parse_fed(kFed, "state_types_test.fed");
    const std::pair<const char*, std::function<void()>> cases[] = {
        {"regions_from_bounds", [&] { regions_from_bounds(fom); }},
        {"regions_overlap", [&] { regions_overlap(fom); }},
        {"federate_regions", [&] { federate_regions(fom); }},
        {"attribute_ownership", attribute_ownership},
        {"save_restore_runs", save_restore_runs},
        {"save_restore_files", save_restore_files},
        {"read_buffer", read_buffer},
        {"viewed_values", viewed_values},
        {"splices_gather", splices_gather},
        {"time_parking", time_parking},
        {"spill_files", spill_files},
    };
    for (const auto& [name, run] : cases) {
        const int before = failures;
        run();
        std::printf("%s %s\n", failures == before ? "ok" : "not ok", name);
    }
    return failures == 0 ? 0 : 1;
}
