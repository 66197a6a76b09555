// The SDK's export macro: libcrowdsim_sdk.so hides every symbol that the SDK's headers do not
// mark with it, so the library exports the SDK and nothing of its internals.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define CROWDSIM_SDK_API __attribute__((visibility("default")))
#else
#define CROWDSIM_SDK_API
#endif
