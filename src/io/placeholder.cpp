namespace sansui::io {}
