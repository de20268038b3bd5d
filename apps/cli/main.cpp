#include <cstdio>
int main() { std::puts("sansui " SANSUI_VERSION); }
