// Versioned schema migrations for the gesture database. The table schema_version records every
// migration applied (version, description, when); opening a database applies the missing ones in
// order, each in its own transaction, so a crash mid-upgrade leaves the previous version intact.
// A database whose version is newer than this build knows is refused rather than misread.
#pragma once

#include "store/sqlite_db.h"

namespace sw::store {

// The schema version this build writes.
int latest_schema_version();
// Applies every missing migration. Returns the version the database is at afterwards.
// Throws DatabaseError on failure or when the file is newer than this build.
int migrate(Database& db);

}  // namespace sw::store
