// The Federate Protocol's session layer (IEEE 1516.1-2025, HLA 4), the RTI's side, as pure state: the 24-byte
// big-endian header every message starts with, the control messages' payloads, and what a session keeps so that
// a dropped connection resumes with no call or callback lost or repeated. No sockets here (session.hpp has
// them), so the decoder is fuzzed and unit-tested on its own (cpp/fuzz/fuzz_fedpro.cpp).
//
// The contract: each side numbers every message it sends after its first (new session, new session status)
// from 1 in a 31-bit space that wraps, and tells in each header the last number it received. Each side keeps
// the HLA messages it sent (the RTI: call responses, callback requests) until the other's header says it has
// them; after a resume each sends again the HLA messages the other had not received (control messages are not
// kept: the numbers of those lost leave gaps), and ignores what it had already received.
#pragma once

#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hlacore::fedpro {

enum class MessageType : std::uint32_t {
    NewSession = 1,
    NewSessionStatus = 2,
    Heartbeat = 3,
    HeartbeatResponse = 4,
    TerminateSession = 5,
    SessionTerminated = 6,
    ResumeRequest = 10,
    ResumeStatus = 11,
    HlaCallRequest = 20,
    HlaCallResponse = 21,
    HlaCallbackRequest = 22,
    HlaCallbackResponse = 23,
};
const char* name(MessageType type);

constexpr std::size_t kHeaderSize = 24;
constexpr std::uint32_t kProtocolVersion = 1;  // the one NewSession asks for
constexpr std::uint32_t kNoSequence = 0x80000000u;  // "none": outside the 31-bit space
constexpr std::uint32_t kSequenceMask = 0x7FFFFFFFu;

// NewSessionStatus's reasons and ResumeStatus's statuses.
enum NewSessionReason : std::uint32_t { kSessionOk = 0, kUnsupportedVersion = 1, kOutOfResources = 2, kBadMessage = 3, kOtherError = 99 };
enum ResumeOutcomeCode : std::uint32_t { kResumeOk = 0, kInvalidSession = 1, kNotEnoughBuffered = 2, kResumeFailed = 99 };

// What breaks the protocol: the connection is closed after it (the standard's "bad message").
struct BadMessage : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Header {
    std::uint32_t size = 0;  // the whole message, header included
    std::uint32_t sequence = 0;
    std::uint64_t session = 0;
    std::uint32_t last_received = kNoSequence;
    MessageType type = MessageType::Heartbeat;
};

// The header at the start of `bytes` (kHeaderSize of them); BadMessage for a size under the header's or over
// `max_size`, or an unknown type.
Header decode_header(std::string_view bytes, std::uint32_t max_size);
std::string encode_header(Header const& h);

// A payload's leading big-endian 32-bit numbers (NewSession: the version; ResumeRequest: last received, oldest
// available; HeartbeatResponse, HlaCallResponse, HlaCallbackResponse: the number answered, then the protobuf).
std::uint32_t payload_u32(std::string_view payload, std::size_t index);
std::string u32s(std::initializer_list<std::uint32_t> values);

// Whether `a` comes after `b` in the wrapping 31-bit space.
bool after(std::uint32_t a, std::uint32_t b);
inline std::uint32_t next(std::uint32_t n) { return (n + 1) & kSequenceMask; }
inline bool valid_sequence(std::uint32_t n) { return (n & ~kSequenceMask) == 0; }

// One session's numbering and what it keeps for a resume.
class SessionState {
public:
    explicit SessionState(std::uint64_t id) : id_(id) {}
    std::uint64_t id() const { return id_; }

    // The bytes of the next message: numbered, stamped with the last number received, and kept when it is an
    // HLA message the federate must not lose.
    std::string frame(MessageType type, std::string_view payload);
    // The first message of a connection (its status): numbered 0, neither counted nor kept.
    std::string first_frame(MessageType type, std::string_view payload) const;
    // A message from the federate: false when it is one received before (sent again after a resume), to be
    // ignored. BadMessage for another session's id or a number outside the space. Lets go of what the header
    // says the federate has.
    bool receive(Header const& h);
    // A resume from the federate: the status, then the kept messages it had not received. The federate is told
    // last_hla_received() and sends again what it kept after it.
    struct Resume {
        std::uint32_t status = kResumeOk;
        std::vector<std::string> resend;
    };
    Resume resume(std::uint32_t last_received_by_federate);

    std::uint32_t last_received() const { return last_received_; }
    // The newest HLA message received (kNoSequence before any): what a resume reports, since a federate keeps
    // only its HLA messages to send again (Pitch's client cannot rewind to a heartbeat's number).
    std::uint32_t last_hla_received() const { return last_hla_received_; }
    std::size_t kept_bytes() const { return kept_bytes_; }
    std::size_t kept_messages() const { return kept_.size(); }

private:
    void release_through(std::uint32_t n);

    std::uint64_t id_;
    std::uint32_t next_ = 1;
    std::uint32_t last_received_ = 0;  // the federate's NewSession is its 0
    std::uint32_t last_hla_received_ = kNoSequence;
    std::uint32_t confirmed_ = 0;      // the newest of ours the federate said it has (our status is 0)
    struct Kept {
        std::uint32_t sequence;
        std::string bytes;
    };
    std::deque<Kept> kept_;
    std::size_t kept_bytes_ = 0;
};

}  // namespace hlacore::fedpro
