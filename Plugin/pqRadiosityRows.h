// A repeatable string property's elements as Qt property links carry them (QVariants).
#ifndef pqRadiosityRows_h
#define pqRadiosityRows_h

#include <QList>
#include <QStringList>
#include <QVariant>

inline QList<QVariant> pqRadiosityToVariants(const QStringList& strings)
{
  QList<QVariant> values;
  for (const QString& s : strings)
  {
    values.push_back(s);
  }
  return values;
}

inline QStringList pqRadiosityToStrings(const QList<QVariant>& values)
{
  QStringList strings;
  for (const QVariant& value : values)
  {
    strings.push_back(value.toString());
  }
  return strings;
}

#endif
