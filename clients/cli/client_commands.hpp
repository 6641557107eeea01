// The `kontakt` commands that talk to a kontaktd daemon:
//   submit DECK.inp|DECK.zip, sweep TEMPLATE.inp PARAMS.csv, status ID, logs ID [-f], wait ID, cancel ID, fetch ID, list.
#pragma once

#include <cstdio>

namespace kontakt::cli {

bool is_client_command(const char* name);
/// Runs `kontakt <command> ...` (argv[1] is the command); returns the exit code.
int client_command(int argc, char** argv);
void print_client_usage(std::FILE* out);

}  // namespace kontakt::cli
