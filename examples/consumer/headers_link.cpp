// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Links the library made of one translation unit per installed header (see CMakeLists.txt).
int main() { return 0; }
