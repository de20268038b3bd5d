// The four seasons: scenes derive their look from them (scene/climate.hpp) and trees change
// their leaves with them (vegetation/).
#pragma once

namespace sansui {

enum class Season { spring, summer, autumn, winter };

}  // namespace sansui
