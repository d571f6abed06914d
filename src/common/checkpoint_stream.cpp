#include "common/checkpoint_stream.hpp"

#include "common/input_error.hpp"

namespace crux {

void CheckpointReader::fail() const { throw InputError(source_, "the checkpoint is truncated or not one crux wrote"); }

}  // namespace crux
