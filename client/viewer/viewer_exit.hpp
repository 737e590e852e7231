// ocean-viewer's exit status, one table for --help, README and the code.
#pragma once

namespace ocean::viewer {

// Every failure also prints its reason on stderr.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;    // GL, window, file: a failure on this machine
inline constexpr int kExitUsage = 2;      // a bad flag or value
inline constexpr int kExitNoServer = 3;   // no frame within --first-frame-timeout: nothing answered
inline constexpr int kExitRefused = 4;    // the server refused the session (profile_unavailable, server_full...)
inline constexpr const char* kExitTable =
    "Exit status: 0 ok, 1 a failure here (GL, window, file), 2 a bad flag or value, 3 no frame within\n"
    "--first-frame-timeout (no server answered), 4 the server refused the session (its reason on stderr).";

}  // namespace ocean::viewer
