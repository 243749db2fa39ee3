#include "run/loop/stop_signals.hpp"

#include <pthread.h>

#include <csignal>
#include <initializer_list>

namespace morphogen {

namespace {
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_stop_signal(int number) {
    g_signal = number;
    std::signal(number, SIG_DFL);  // async-signal-safe; a second signal ends the process
}
}  // namespace

StopSignals::StopSignals() {
    g_signal = 0;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    action.sa_flags = SA_RESTART;  // file I/O in progress simply continues
    sigemptyset(&action.sa_mask);
    sigset_t stops;
    sigemptyset(&stops);
    for (int number : {SIGINT, SIGTERM}) {
        // A signal started ignored (`nohup`, a shell's background job for
        // SIGINT) stays ignored, as in shells and most tools: it was meant
        // for someone else.
        struct sigaction before {};
        sigaction(number, nullptr, &before);
        if (before.sa_handler == SIG_IGN) continue;
        sigaction(number, &action, nullptr);
        sigaddset(&stops, number);
    }
    // A launcher may block these across exec to close the moment before any
    // of our code runs (a signal then waits, pending); from here on they are
    // stop requests, so let them in (a pending one arrives right now).
    pthread_sigmask(SIG_UNBLOCK, &stops, nullptr);
}

bool StopSignals::requested() { return g_signal != 0; }
int StopSignals::signal_number() { return g_signal; }

}  // namespace morphogen
