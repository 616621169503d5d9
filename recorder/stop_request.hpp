#pragma once
// Ctrl-C (SIGINT) and SIGTERM as a polite request: the first one sets a flag that the recording loop
// checks, so the recording is finished properly and the file stays playable; a second one ends the
// program at once (the default action is restored after the first).
namespace rdsf::recorder {

/// Installs the handlers. Call once, before the loop.
void install_stop_request_handlers();

/// True once SIGINT or SIGTERM arrived.
bool stop_requested();

}  // namespace rdsf::recorder
