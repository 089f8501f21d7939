#include "cli/command.h"

int main(int argc, char** argv) { return geovis::cli::run(argc, argv); }
