// The program that builds the precompiled header shared by the test programs
// (tests/CMakeLists.txt).
int
main()
{
  return 0;
}
