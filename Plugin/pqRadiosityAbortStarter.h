// Makes ParaView 5.11's abort button stop the radiosity filters (builtin session).
#ifndef pqRadiosityAbortStarter_h
#define pqRadiosityAbortStarter_h

#include <QObject>
#include <QPointer>

class QAbstractButton;

/**
 * ParaView 5.11 leaves its abort button disabled, connects nothing to it, and runs no Qt
 * events while a filter executes, so a click could not arrive anyway. While one of this
 * plugin's filters reports progress, this auto-start enables the button, lets Qt deliver
 * events at each progress report, swallows every other user input (a click elsewhere must
 * not start a render or another pipeline update from inside the running filter), and
 * turns a click on the button into vtkRadiosityRequestAbort(). Remote sessions
 * and recorded test playback are left alone, as ParaView 6.1 does when it pumps events.
 */
class pqRadiosityAbortStarter : public QObject
{
  Q_OBJECT

public:
  explicit pqRadiosityAbortStarter(QObject* parent = nullptr);
  void startup();
  void shutdown();

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void onProgress(const QString& text, int value);
  void onProgressEnd();
  void onAbort();
  void Activate();
  bool MayProcessEvents() const;

  QPointer<QAbstractButton> AbortButton;
  bool Active = false;
  bool Processing = false;
  bool WasUnblocked = false; ///< ParaView's own input blocking, restored at the end
};

#endif
