#include <cstdio>

int main()
{
  std::puts("aniso");
  return 0;
}
