# cmake -DINPUT=file -DOUTPUT=header.h -DNAME=kName -P embed_text.cmake: writes a header that
# holds the file's text as `inline constexpr std::string_view NAME`.
file(READ ${INPUT} text)
string(FIND "${text}" ")colav_embedded\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )colav_embedded\"")
endif()
file(WRITE ${OUTPUT}.tmp "// Generated from ${INPUT} by embed_text.cmake; do not edit.\n"
  "#pragma once\n#include <string_view>\nnamespace colav {\n"
  "inline constexpr std::string_view ${NAME} = R\"colav_embedded(${text})colav_embedded\";\n"
  "}  // namespace colav\n")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
