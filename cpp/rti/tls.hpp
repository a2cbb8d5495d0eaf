// Optional TLS (docs/networking.md): the gateway with a certificate and key (rtig --tls-cert/--tls-key) makes
// every TCP connection TLS; a client given tls verifies the gateway's certificate chain and the host it
// connected to. OpenSSL's libssl on the non-blocking sockets of the reactor and of the client: the callers
// drive SSL_read/SSL_write and wait on the descriptor themselves (SSL_ERROR_WANT_READ/WANT_WRITE).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include <openssl/ssl.h>

namespace hlacore::tls {

struct ContextFree {
    void operator()(SSL_CTX* ctx) const { SSL_CTX_free(ctx); }
};
struct SessionFree {
    void operator()(SSL* ssl) const { SSL_free(ssl); }
};
using Context = std::unique_ptr<SSL_CTX, ContextFree>;
using Session = std::unique_ptr<SSL, SessionFree>;

// The gateway's context: TLS 1.2 at least (1.3 preferred), the certificate (chain) and private key in PEM
// files; the key file must be readable by its owner only. Throws std::runtime_error saying why not.
Context server_context(const std::string& cert_file, const std::string& key_file);
// A client's context, verifying the gateway's certificate: against the system's default CA store when
// `ca_file` is empty, else against the CA certificate(s) in that PEM file (a self-signed certificate, or the
// gateway's own certificate, may be given as well: it is then trusted as it is). Throws std::runtime_error.
Context client_context(const std::string& ca_file);

// An SSL object on the non-blocking socket `fd` (which it does not close), its writes with MSG_NOSIGNAL: a
// peer gone while the gateway writes must not raise SIGPIPE in the process. Partial writes are on and the
// buffer may move between retries (the caller's output buffer grows and is compacted).
Session session(SSL_CTX* ctx, int fd);
// For a client: check that the certificate names `host` (an IP address: its IP SANs; a name: its DNS names,
// also sent as SNI).
void expect_host(SSL* ssl, const std::string& host);

// Whether `bytes` begin like a TLS record (a handshake or an alert, TLS 1.x): what a TLS peer sends first.
// No hlacore frame starts so before the handshake's end: its length field is small.
inline bool looks_like_record(std::string_view bytes) {
    return bytes.size() >= 2 && (bytes[0] == 0x16 || bytes[0] == 0x15) && bytes[1] == 0x03;
}

// OpenSSL's error queue as one line (emptied); `fallback` when it is empty.
std::string errors(const std::string& fallback = "");

}  // namespace hlacore::tls
