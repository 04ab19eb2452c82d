// Per-frame work that stops at its first failure: a component's Update that
// throws would throw again every frame (the same error flooding the console
// at the frame rate). The first exception is reported, once; from then on
// Run does nothing and returns false, and the caller disables itself.
using System;

namespace Smg
{
    public sealed class SmgFailOnce
    {
        readonly Action<Exception> report;

        /// <param name="report">Gets the first exception (e.g. logs it).</param>
        public SmgFailOnce(Action<Exception> report)
        {
            this.report = report ?? throw new ArgumentNullException(nameof(report));
        }

        /// <summary>The exception that stopped the work (null while none).</summary>
        public Exception Failure { get; private set; }

        /// <summary>Runs `work` unless an earlier run failed; false when
        /// this run or an earlier one failed. Pass a delegate created once
        /// (not a new lambda per frame) to keep frames allocation-free.</summary>
        public bool Run(Action work)
        {
            if (Failure != null)
                return false;
            try
            {
                work();
                return true;
            }
            catch (Exception e)
            {
                Failure = e;
                report(e);
                return false;
            }
        }
    }
}
