// libFuzzer harness of session files: the bytes go through Qt's JSON parser and, when they make
// an object, through sessionFromJson, which checks every type, range and choice. Accepted
// outcomes: content, or an aniso::Error naming the file and the key at fault.
#include "core/error.h"
#include "scene/Session.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<int>(size));
  QJsonParseError error{};
  const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
  if (error.error != QJsonParseError::NoError || !document.isObject())
  {
    return 0;
  }
  try
  {
    aniso::sessionFromJson(document.object(), QStringLiteral("/nonexistent"),
                           QStringLiteral("fuzz.aniso"));
  }
  catch (const aniso::Error&)
  {
  }
  return 0;
}
