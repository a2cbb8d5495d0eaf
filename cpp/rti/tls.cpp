#include "rti/tls.hpp"

#include "rti/auth.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <arpa/inet.h>
#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>
#include <sys/socket.h>
#include <sys/stat.h>

namespace hlacore::tls {
namespace {

// A socket BIO of our own: OpenSSL's writes with write(2), which raises SIGPIPE when the peer is gone; this
// one sends with MSG_NOSIGNAL (as the plain paths do), never blocks, and never closes the descriptor.
int socket_of(BIO* bio) { return static_cast<int>(reinterpret_cast<std::intptr_t>(BIO_get_data(bio))); }

int bio_write(BIO* bio, const char* data, int length) {
    BIO_clear_retry_flags(bio);
    for (;;) {
        const ssize_t n = ::send(socket_of(bio), data, static_cast<std::size_t>(length), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n >= 0) return static_cast<int>(n);
        if (errno == EINTR) continue;
        if (errno == EAGAIN || errno == EWOULDBLOCK) BIO_set_retry_write(bio);
        return -1;
    }
}

int bio_read(BIO* bio, char* data, int length) {
    BIO_clear_retry_flags(bio);
    for (;;) {
        const ssize_t n = ::recv(socket_of(bio), data, static_cast<std::size_t>(length), MSG_DONTWAIT);
        if (n > 0) return static_cast<int>(n);
        if (n == 0) {
            BIO_set_flags(bio, BIO_FLAGS_IN_EOF);  // BIO_eof(): how OpenSSL tells the end of the stream
            return 0;
        }
        if (errno == EINTR) continue;
        if (errno == EAGAIN || errno == EWOULDBLOCK) BIO_set_retry_read(bio);
        return -1;
    }
}

int bio_puts(BIO* bio, const char* text) { return bio_write(bio, text, static_cast<int>(std::strlen(text))); }

long bio_ctrl(BIO* bio, int command, long, void*) {
    switch (command) {
        case BIO_CTRL_FLUSH: return 1;  // nothing is buffered here
        case BIO_CTRL_EOF: return BIO_test_flags(bio, BIO_FLAGS_IN_EOF) != 0;
        default: return 0;
    }
}

int bio_create(BIO* bio) {
    BIO_set_init(bio, 1);
    return 1;
}

const BIO_METHOD* socket_method() {
    static BIO_METHOD* const method = [] {
        BIO_METHOD* m = BIO_meth_new(BIO_get_new_index() | BIO_TYPE_SOURCE_SINK, "hlacore socket");
        if (!m) throw std::runtime_error("OpenSSL: no BIO method");
        BIO_meth_set_write(m, bio_write);
        BIO_meth_set_read(m, bio_read);
        BIO_meth_set_puts(m, bio_puts);
        BIO_meth_set_ctrl(m, bio_ctrl);
        BIO_meth_set_create(m, bio_create);
        return m;
    }();
    return method;
}

void require_readable(const std::string& path, const std::string& what) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw std::runtime_error("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw std::runtime_error(what + " '" + path + "' is not a file");
}

Context new_context(const SSL_METHOD* method) {
    Context ctx(SSL_CTX_new(method));
    if (!ctx) throw std::runtime_error("OpenSSL: no TLS context: " + errors());
    SSL_CTX_set_min_proto_version(ctx.get(), TLS1_2_VERSION);
    // No renegotiation (TLS 1.2): a read never has to write nor a write to read once the handshake is done.
    // An end of the stream without close_notify is an end like any other: the frames say whether one was cut.
    SSL_CTX_set_options(ctx.get(), SSL_OP_NO_RENEGOTIATION | SSL_OP_IGNORE_UNEXPECTED_EOF);
    // One recv() for what the socket has rather than one for each record's header and another for its body.
    // The readers then go on with SSL_read while SSL_has_pending(): what stays in the session after they
    // stop is at most the start of a record whose rest is still to come through the socket.
    SSL_CTX_set_read_ahead(ctx.get(), 1);
    return ctx;
}

}  // namespace

std::string errors(const std::string& fallback) {
    std::string text;
    while (unsigned long e = ERR_get_error()) {
        const char* reason = ERR_reason_error_string(e);
        char buffer[256];
        if (!reason) {
            ERR_error_string_n(e, buffer, sizeof buffer);
            reason = buffer;
        }
        if (text.find(reason) != std::string::npos) continue;
        if (!text.empty()) text += "; ";
        text += reason;
    }
    return text.empty() ? fallback : text;
}

Context server_context(const std::string& cert_file, const std::string& key_file) {
    require_readable(cert_file, "the TLS certificate");
    require_readable(key_file, "the TLS key file");
    auth::require_owner_only(key_file, "the TLS key file");
    Context ctx = new_context(TLS_server_method());
    SSL_CTX_set_options(ctx.get(), SSL_OP_CIPHER_SERVER_PREFERENCE);
    // Clients do not resume sessions: no tickets, no cache.
    SSL_CTX_set_num_tickets(ctx.get(), 0);
    SSL_CTX_set_session_cache_mode(ctx.get(), SSL_SESS_CACHE_OFF);
    ERR_clear_error();
    if (SSL_CTX_use_certificate_chain_file(ctx.get(), cert_file.c_str()) != 1)
        throw std::runtime_error("cannot use the TLS certificate '" + cert_file + "': " + errors("not a PEM certificate"));
    const std::string mismatch = "the TLS key '" + key_file + "' does not belong to the certificate '" + cert_file + "'";
    if (SSL_CTX_use_PrivateKey_file(ctx.get(), key_file.c_str(), SSL_FILETYPE_PEM) != 1) {
        if (ERR_GET_REASON(ERR_peek_last_error()) == X509_R_KEY_VALUES_MISMATCH) {
            ERR_clear_error();
            throw std::runtime_error(mismatch);
        }
        throw std::runtime_error("cannot use the TLS key '" + key_file + "': " + errors("not a PEM private key"));
    }
    if (SSL_CTX_check_private_key(ctx.get()) != 1)
        throw std::runtime_error(mismatch + ": " + errors());
    return ctx;
}

Context client_context(const std::string& ca_file) {
    Context ctx = new_context(TLS_client_method());
    SSL_CTX_set_verify(ctx.get(), SSL_VERIFY_PEER, nullptr);
    ERR_clear_error();
    if (ca_file.empty()) {
        if (SSL_CTX_set_default_verify_paths(ctx.get()) != 1)
            throw std::runtime_error("no system CA store for TLS: " + errors());
        return ctx;
    }
    require_readable(ca_file, "the TLS CA file");
    if (SSL_CTX_load_verify_locations(ctx.get(), ca_file.c_str(), nullptr) != 1)
        throw std::runtime_error("cannot use the TLS CA file '" + ca_file + "': " + errors("no PEM certificate in it"));
    // A certificate in the file is a trust anchor as it is, self-signed or not: the gateway's own
    // certificate may be given (pinned) instead of the CA that signed it.
    X509_VERIFY_PARAM_set_flags(SSL_CTX_get0_param(ctx.get()), X509_V_FLAG_PARTIAL_CHAIN);
    return ctx;
}

Session session(SSL_CTX* ctx, int fd) {
    Session ssl(SSL_new(ctx));
    BIO* bio = ssl ? BIO_new(socket_method()) : nullptr;
    if (!bio) throw std::runtime_error("OpenSSL: no TLS session: " + errors());
    BIO_set_data(bio, reinterpret_cast<void*>(static_cast<std::intptr_t>(fd)));
    SSL_set_bio(ssl.get(), bio, bio);  // one reference, taken by the session
    SSL_set_mode(ssl.get(), SSL_MODE_ENABLE_PARTIAL_WRITE | SSL_MODE_ACCEPT_MOVING_WRITE_BUFFER);
    return ssl;
}

void expect_host(SSL* ssl, const std::string& host) {
    unsigned char address[16];
    if (inet_pton(AF_INET, host.c_str(), address) == 1 || inet_pton(AF_INET6, host.c_str(), address) == 1) {
        X509_VERIFY_PARAM_set1_ip_asc(SSL_get0_param(ssl), host.c_str());
        return;
    }
    SSL_set_hostflags(ssl, X509_CHECK_FLAG_NO_PARTIAL_WILDCARDS);
    SSL_set1_host(ssl, host.c_str());
    SSL_set_tlsext_host_name(ssl, host.c_str());
}

}  // namespace hlacore::tls
