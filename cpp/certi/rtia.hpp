// hlacore-rtia: a drop-in for CERTI's `rtia` (docs/certi.md). A CERTI-built federate (its libRTI, JCERTI,
// PyHLA over that libRTI) starts it and speaks CERTI's federate protocol to it (protocol.hpp); each request
// becomes a call of hlacore's client, each callback a message back, delivered one at a time within the
// federate's tick. The gateway is named as for hlacore's own API ($HLACORE_RTIG, else CERTI_HOST and
// CERTI_TCP_PORT).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "certi/protocol.hpp"
#include "rti/client/client.hpp"

namespace hlacore::certi {

// What the rtia says on stderr beyond its errors ($HLACORE_RTIA_TRACE): each message in and out ("1", as
// CERTI's RTIA_MSG=D), or at the end how many of each type the federate sent ("counts", as CERTI's rtia
// statistics).
enum class Trace { Off, Messages, Counts };

// The federate's end: frames read and written whole, in the federate's byte order.
class FederateLink {
public:
    FederateLink(int fd, Trace trace) : fd_(fd), trace_(trace) {}
    ~FederateLink();
    FederateLink(const FederateLink&) = delete;
    FederateLink& operator=(const FederateLink&) = delete;

    // The next message; nullopt when the federate closed the connection. ProtocolError for a frame that is not
    // one, std::system_error when reading fails.
    std::optional<Message> receive();
    void send(const Message& m);
    // Whether the federate hung up (checked without reading, while it is blocked in tick).
    bool gone() const;
    int fd() const { return fd_; }
    // With Trace::Counts: the messages received of each type, on stderr.
    void print_counts() const;

private:
    int fd_;
    Trace trace_;
    bool big_endian_ = false;  // the federate's byte order, from its last frame
    std::array<std::uint64_t, static_cast<std::size_t>(Type::LAST)> received_{};
};

class Rtia {
public:
    Rtia(int federate_fd, Trace trace) : link_(federate_fd, trace) {}
    // Serves the federate until it closes the connection; a federate that is joined when it vanishes is
    // resigned as a dead one would be. Returns the process' exit status.
    int run();

private:
    int serve_federate();  // run()'s loop
    // The answer to one request (CERTI answers every request but tick's with a message of its type).
    Message answer(const Message& request);
    Message serve(const Message& request);  // requests.cpp: the call of hlacore's client
    // TICK_REQUEST: callbacks one at a time, each acknowledged by the federate; TICK_REQUEST back to end it.
    void tick(const Message& request);
    // Waits for the federate's TICK_REQUEST_NEXT or _STOP (true: stop), serving its requests meanwhile (a
    // callback may call services).
    bool await_acknowledgement();
    // The message of a callback (callbacks.cpp).
    Message message_of(wire::Message& callback);
    Client& client();

    FederateLink link_;
    std::optional<Client> client_;
    bool joined_ = false;
    bool in_callback_ = false;
    bool closed_ = false;
};

// The FED file a CERTI federate names, found as CERTI finds it: the path as given, then each directory of
// $CERTI_FOM_PATH, then $CERTI_HOME/share/federations. Its text, empty when not found here (the gateway looks it up in its --fom-path then).
std::string find_file(const std::string& fed, std::string& path_found);
// The same, checked (ErrorReadingFED with FILE:LINE:COL at the federate's call).
std::string find_fed(const std::string& fed, std::string& path_found);

}  // namespace hlacore::certi
