// hlacore-rtia: started by a CERTI-built federate in place of CERTI's rtia (docs/certi.md). CERTI's libRTI runs
// `$CERTI_RTIA -f FD` (its end of a socket pair) or, built for TCP, `rtia -p PORT`; JCERTI `rtia -p PORT`:
// the federate listens on that port of the loopback interface and the rtia connects to it.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "certi/rtia.hpp"
#include "rti/options.hpp"

namespace {

struct Command {
    int fd = -1;
    int port = -1;
};

const hlacore::Options<Command>& command_options() {
    using Text = const std::string&;
    static const hlacore::Options<Command> table = {
        {"-f", nullptr, nullptr, "FD", false,
         [](Command& c, Text t) { c.fd = static_cast<int>(hlacore::whole_number(t, 0, 1 << 20, "a descriptor")); },
         nullptr, "the federate's end of the socket pair it made (CERTI's libRTI)"},
        {"-p", nullptr, nullptr, "PORT", false,
         [](Command& c, Text t) { c.port = static_cast<int>(hlacore::whole_number(t, 1, 65535, "a port")); },
         nullptr, "connect to the federate on this TCP port of 127.0.0.1 (JCERTI, libRTI built for TCP)"},
        {"-v", nullptr, nullptr, nullptr, false, [](Command&, Text) {}, nullptr, "accepted, as CERTI's rtia does"},
    };
    return table;
}

int usage(int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: hlacore-rtia (-f FD | -p PORT) [-v]\n%s"
                 "The gateway: $HLACORE_RTIG (HOST:PORT), else CERTI_HOST and CERTI_TCP_PORT (docs/certi.md).\n",
                 hlacore::help_entries(command_options()).c_str());
    return status;
}

int connect_loopback(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return -1;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        ::close(fd);
        return -1;
    }
    const int on = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    return fd;
}

}  // namespace

int main(int argc, char** argv) {
    Command command;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") return usage(0);
        const auto* option = hlacore::find_option(command_options(), arg, hlacore::Given::Flag);
        if (!option) {
            std::fprintf(stderr, "hlacore-rtia: unknown option %s\n", arg.c_str());
            return usage(2);
        }
        try {
            if (option->metavar && ++i == argc) throw hlacore::OptionError(arg + " needs a value");
            hlacore::apply(command, *option, hlacore::Given::Flag, option->metavar ? argv[i] : "1");
        } catch (const hlacore::OptionError& e) {
            std::fprintf(stderr, "hlacore-rtia: %s\n", e.what());
            return 2;
        }
    }
    if ((command.fd < 0) == (command.port < 0)) return usage(2);
    std::signal(SIGPIPE, SIG_IGN);
    int fd = command.fd;
    if (command.port >= 0) {
        fd = connect_loopback(command.port);
        if (fd < 0) {
            std::fprintf(stderr, "hlacore-rtia: cannot reach the federate at 127.0.0.1:%d: %s\n", command.port,
                         std::strerror(errno));
            return 1;
        }
    }
    using hlacore::certi::Trace;
    const char* trace = std::getenv("HLACORE_RTIA_TRACE");
    const std::string t = trace ? trace : "";
    return hlacore::certi::Rtia(fd, t == "1" ? Trace::Messages : t == "counts" ? Trace::Counts : Trace::Off).run();
}
