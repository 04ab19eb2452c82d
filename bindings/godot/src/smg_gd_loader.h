/* smg_gd_loader.h - SmgGraphLoader, the ResourceFormatLoader for .smg files. */
#ifndef SMG_GD_LOADER_H
#define SMG_GD_LOADER_H

void smg_gd_loader_register(void);
void smg_gd_loader_unregister(void);

#endif
