namespace sansui::render {}
