#pragma once
// Ctrl-C / SIGTERM as a request to stop cleanly: the run finishes its current
// batch, checkpoints and exits 130. The first signal only sets a flag; the
// handler then restores the default action, so a second Ctrl-C kills at once
// (the last checkpoint stays valid either way). `evolve` and `resume` make one
// first thing, before they read or create anything, so a signal during
// start-up is a stop request like any other, never a death by the signal.
namespace morphogen {

class StopSignals {
public:
    StopSignals();   // installs the handlers and clears the flag
    ~StopSignals();  // restores the previous handlers
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    static bool requested();
    static int signal_number();  // the signal received (0 if none)
};

}  // namespace morphogen
