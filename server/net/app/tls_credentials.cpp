#include "tls_credentials.hpp"

#include <openssl/err.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace ocean::server {

namespace {

// OpenSSL's reasons for the failure: the first (the cause, "no start line", which asio has taken
// off the queue into `error`), then what is left on the queue ("PEM lib").
std::string openssl_reason(const std::error_code& error) {
  std::string text = error ? error.message() : std::string();
  while (const unsigned long code = ERR_get_error()) {
    const char* reason = ERR_reason_error_string(code);
    if (reason && text.find(reason) == std::string::npos) text += (text.empty() ? "" : ", ") + std::string(reason);
  }
  return text.empty() ? std::string("no reason given") : text;
}

// Empty when the file opens for reading, else why not ("No such file or directory").
std::string unreadable(const std::string& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) return std::strerror(errno);
  std::fclose(f);
  return {};
}

}  // namespace

std::optional<TlsCredentials> TlsCredentials::load(const std::string& cert_file, const std::string& key_file, std::string& error) {
  TlsCredentials credentials(cert_file, key_file);
  credentials.context_ = credentials.read(error);
  if (!credentials.context_) return std::nullopt;
  return credentials;
}

TlsCredentials::TlsCredentials(TlsCredentials&& other) noexcept
    : cert_file_(std::move(other.cert_file_)), key_file_(std::move(other.key_file_)), context_(std::move(other.context_)) {}

std::shared_ptr<asio::ssl::context> TlsCredentials::read(std::string& error) const {
  // TLS 1.2 and 1.3 only: what every browser that runs WebAssembly speaks.
  auto context = std::make_shared<asio::ssl::context>(asio::ssl::context::tls_server);
  context->set_options(asio::ssl::context::default_workarounds | asio::ssl::context::no_sslv2 |
                       asio::ssl::context::no_sslv3 | asio::ssl::context::no_tlsv1 | asio::ssl::context::no_tlsv1_1 |
                       asio::ssl::context::single_dh_use);
  for (const auto& [flag, file] : {std::pair{"--tls-cert", cert_file_}, std::pair{"--tls-key", key_file_}})
    if (const std::string why = unreadable(file); !why.empty()) {
      error = std::string(flag) + " '" + file + "': cannot read it: " + why;
      return nullptr;
    }
  std::error_code code;
  context->use_certificate_chain_file(cert_file_, code);
  if (code) {
    error = "--tls-cert '" + cert_file_ + "': not a PEM certificate chain (" + openssl_reason(code) + ")";
    return nullptr;
  }
  context->use_private_key_file(key_file_, asio::ssl::context::pem, code);
  if (code) {
    error = "--tls-key '" + key_file_ + "': not a PEM private key, or not the certificate's (" + openssl_reason(code) + ")";
    return nullptr;
  }
  if (SSL_CTX_check_private_key(context->native_handle()) != 1) {
    error = "--tls-key '" + key_file_ + "' is not the key of --tls-cert '" + cert_file_ + "': " + openssl_reason({});
    return nullptr;
  }
  return context;
}

std::shared_ptr<asio::ssl::context> TlsCredentials::current() const {
  std::lock_guard lock(mutex_);
  return context_;
}

std::string TlsCredentials::reload() {
  std::string error;
  auto fresh = read(error);
  if (!fresh) return error;
  std::lock_guard lock(mutex_);
  context_ = std::move(fresh);
  return {};
}

}  // namespace ocean::server
