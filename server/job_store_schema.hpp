// The versioned schema of the job store: numbered migrations, applied in order, each in its
// own transaction that also bumps PRAGMA user_version.
#pragma once

#include "server/sqlite_db.hpp"

namespace kontakt::server {

/// The schema version this build writes.
int schema_version();

/// Brings the database up to schema_version(); refuses a database from a newer build.
void migrate(SqliteDb& db);

}  // namespace kontakt::server
