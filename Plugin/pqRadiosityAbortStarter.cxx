#include "pqRadiosityAbortStarter.h"

#include "vtkRadiosityAbort.h"

#include "pqApplicationCore.h"
#include "pqCoreConfiguration.h"
#include "pqCoreUtilities.h"
#include "pqProgressManager.h"
#include "pqServer.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCoreApplication>
#include <QEvent>
#include <QWidget>

namespace
{
/// Progress texts are class names without "vtk"; all of this plugin's filters have this.
bool IsRadiosityFilter(const QString& text)
{
  return text.contains(QLatin1String("Radiosity"));
}

/// Input that could start work (render, interaction, another Apply) inside a running filter.
bool IsUserInput(QEvent::Type type)
{
  switch (type)
  {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::Shortcut:
    case QEvent::ShortcutOverride:
    case QEvent::ContextMenu:
    case QEvent::DragEnter:
    case QEvent::DragMove:
    case QEvent::Drop:
    case QEvent::TouchBegin:
    case QEvent::TouchUpdate:
    case QEvent::TouchEnd:
    case QEvent::Close:
      return true;
    default:
      return false;
  }
}
}

pqRadiosityAbortStarter::pqRadiosityAbortStarter(QObject* parent)
  : QObject(parent)
{
}

void pqRadiosityAbortStarter::startup()
{
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  QObject::connect(progress, &pqProgressManager::progress, this, &pqRadiosityAbortStarter::onProgress);
  QObject::connect(
    progress, &pqProgressManager::progressEndEvent, this, &pqRadiosityAbortStarter::onProgressEnd);
  QObject::connect(progress, &pqProgressManager::abort, this, &pqRadiosityAbortStarter::onAbort);
}

void pqRadiosityAbortStarter::shutdown()
{
  this->onProgressEnd();
}

void pqRadiosityAbortStarter::onProgress(const QString& text, int value)
{
  if (!IsRadiosityFilter(text) || !this->MayProcessEvents())
  {
    return;
  }
  this->Activate();
  // ParaView skips zero progress too: timers that expect an order break otherwise.
  if (value > 0 && !this->Processing)
  {
    this->Processing = true;
    QCoreApplication::processEvents();
    this->Processing = false;
  }
}

bool pqRadiosityAbortStarter::MayProcessEvents() const
{
  pqServer* server = pqApplicationCore::instance()->getActiveServer();
  return server && !server->isRemote() && pqCoreConfiguration::instance()->testScriptCount() == 0;
}

void pqRadiosityAbortStarter::Activate()
{
  if (this->Active)
  {
    return;
  }
  this->Active = true;
  if (!this->AbortButton)
  {
    if (QWidget* main = pqCoreUtilities::mainWidget())
    {
      this->AbortButton = main->findChild<QAbstractButton*>(QStringLiteral("AbortButton"));
    }
  }
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  progress->setEnableAbort(true);
  // ParaView's own filter drops every press that is not aimed at the button itself, and a
  // real click is first aimed at the window; ours judges at the widget instead.
  this->WasUnblocked = progress->unblockEvents(true);
  QCoreApplication::instance()->installEventFilter(this);
}

void pqRadiosityAbortStarter::onProgressEnd()
{
  if (!this->Active)
  {
    return;
  }
  this->Active = false;
  QCoreApplication::instance()->removeEventFilter(this);
  vtkRadiosityClearAbort(); // the abort covered this whole update, every filter in it
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  progress->unblockEvents(this->WasUnblocked);
  progress->setEnableAbort(false);
}

void pqRadiosityAbortStarter::onAbort()
{
  if (this->Active)
  {
    vtkRadiosityRequestAbort();
  }
}

bool pqRadiosityAbortStarter::eventFilter(QObject* watched, QEvent* event)
{
  if (!this->Active || !IsUserInput(event->type()))
  {
    return false;
  }
  QWidget* widget = qobject_cast<QWidget*>(watched);
  if (!widget)
  {
    // A real click reaches the window (a QWindow) first, which passes it to the widget
    // under the mouse; that delivery is where it is judged.
    return false;
  }
  const auto within = [widget](QWidget* root) {
    return root && widget && (widget == root || root->isAncestorOf(widget));
  };
  // A modal dialog opened meanwhile (a timer's) runs its own loop: it must stay usable.
  return !within(this->AbortButton) && !within(QApplication::activeModalWidget());
}
