// Links the library made of one translation unit per installed header (see CMakeLists.txt).
int main() { return 0; }
