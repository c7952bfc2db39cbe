#pragma once
#include "nckit/core/toml_table_reader.hpp"
