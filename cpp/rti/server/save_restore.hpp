// Save/restore (HLA 1.3 §4.11-4.22) of one federation at the gateway: the saves kept, the save or restore
// under way, who has answered, and what is held from the federates in it. The Federation runs the protocol
// with it and makes the snapshots (server/save_restore.cpp, docs/save-restore.md). Nothing here is looked at
// on the message path but `restoring`, which is a flag test while no restore runs.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "rti/server/outbox.hpp"

namespace hlacore {

class SaveRestore {
public:
    // A save or a restore in progress.
    struct Run {
        bool active = false;
        std::string label;
        // federateSaveComplete / federateRestoreComplete (true), or the NotComplete one (false).
        std::map<FederateHandle, bool> answered;
        bool failed = false;  // a federate left meanwhile
        std::map<FederateHandle, std::vector<std::string>> held;  // frames held from the federates in it
        void departed(FederateHandle federate) {
            answered.erase(federate);
            held.erase(federate);
            failed = true;
        }
        // Why it did not succeed: a federate left, else one reported a failure (numbered alike for a restore).
        std::uint8_t reason() const {
            return static_cast<std::uint8_t>(failed ? wire::SaveFailure::FederateResigned : wire::SaveFailure::FederateReported);
        }
    };
    struct SaveRun : Run {
        wire::OptionalTime time;        // a timed save
        std::set<FederateHandle> told;  // sent initiateFederateSave
    };

    SaveRun save;
    Run restore;
    std::string dir;                           // where saves are written as files ("": in memory only)
    std::map<std::string, std::string> saves;  // label -> encoded save, this gateway's run
    std::string error;                         // why the gateway could not keep the last save, if it could not

    // SaveNotInProgress or RestoreNotInProgress unless one runs (IEEE 1516-2010's aborts).
    void check_saving() const;
    void check_restoring() const;
    // SaveInProgress or RestoreInProgress, naming `service`, while a save or a restore runs.
    void check_idle(const char* service) const;
    // RestoreInProgress while a restore runs (registering an object: the restore replaces the objects).
    void check_not_restoring() const;
    // While a restore runs, what a federate sends before its federateRestoreComplete is dropped.
    bool restoring(FederateHandle from) const { return restore.active && !restore.answered.count(from); }
    // Grants and deliveries wait while every one of the `joined` federates saves or restores.
    bool time_frozen(std::size_t joined) const { return restore.active || (save.active && save.told.size() >= joined); }
    // The file of the save `label` of `federation` in `dir`.
    std::string file(const std::string& federation, const std::string& label) const;
    // Keeps a finished save by its label and, with a `dir`, in its file (written beside, then renamed: a
    // crash never leaves half a save under the label's name). False, with `error` set, when the file could
    // not be written; the save is not kept then.
    bool keep(const std::string& federation, const std::string& label, std::string bytes);
};

}  // namespace hlacore
