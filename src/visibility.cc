// visibility.cc -- (being written)
#include <config.h>
